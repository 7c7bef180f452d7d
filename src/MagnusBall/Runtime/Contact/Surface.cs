using System;

namespace MagnusBall.Contact
{
    /// <summary>
    /// What a court or ground does to a bouncing ball: the contact parameters of the Cross slide/grip
    /// bounce (<see cref="CrossBounce"/>). Immutable and safe to share between threads.
    /// </summary>
    /// <remarks>
    /// <para>The parameters are those of Cross's bounce model (Cross 2002, Am. J. Phys. 70; Cross 2005,
    /// Am. J. Phys. 73; Cross 2020, Sports Eng. 23:9) and Brody's court measurements:</para>
    /// <list type="bullet">
    /// <item><description>normal coefficient of restitution e_y = e0 - k theta1 (theta1 the incoming angle from the
    /// surface in degrees), clamped to [0, 1];</description></item>
    /// <item><description>sliding (kinetic) friction coefficient mu;</description></item>
    /// <item><description>tangential coefficient of restitution e_x for a ball that grips (the slip of the contact
    /// point reverses to -e_x times its incoming value);</description></item>
    /// <item><description>normal-force offset D = D0 + D1 v1 (v1 the incoming speed): the normal reaction acts a
    /// distance D ahead of the ball's centre and resists its rolling.</description></item>
    /// </list>
    /// </remarks>
    public sealed class Surface
    {
        /// <summary>Creates a surface.</summary>
        /// <param name="name">A short name for reports ("hard", "clay", ...); not null.</param>
        /// <param name="normalRestitution">e0, the normal COR at grazing incidence; in [0, 1].</param>
        /// <param name="normalRestitutionPerDegree">k in e_y = e0 - k theta1, per degree; finite (the result is clamped to [0, 1]).</param>
        /// <param name="slidingFriction">mu, the sliding friction coefficient; finite and &gt;= 0.</param>
        /// <param name="tangentialRestitution">e_x, the tangential COR in grip; in [0, 1].</param>
        /// <param name="forceOffset">D0, the speed-independent part of the normal-force offset, m; finite and &gt;= 0.</param>
        /// <param name="forceOffsetPerSpeed">D1 in D = D0 + D1 v1, s (m per m/s); finite and &gt;= 0.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public Surface(
            string name,
            double normalRestitution,
            double normalRestitutionPerDegree,
            double slidingFriction,
            double tangentialRestitution,
            double forceOffset,
            double forceOffsetPerSpeed)
        {
            Require.NotNull(name, nameof(name));
            Require.InRange(normalRestitution, 0, 1, nameof(normalRestitution));
            Require.Finite(normalRestitutionPerDegree, nameof(normalRestitutionPerDegree));
            Require.NonNegative(slidingFriction, nameof(slidingFriction));
            Require.InRange(tangentialRestitution, 0, 1, nameof(tangentialRestitution));
            Require.NonNegative(forceOffset, nameof(forceOffset));
            Require.NonNegative(forceOffsetPerSpeed, nameof(forceOffsetPerSpeed));
            Name = name;
            Contact = new ContactProperties(
                normalRestitution, slidingFriction, tangentialRestitution, forceOffset, normalRestitutionPerDegree, forceOffsetPerSpeed);
        }

        /// <summary>The same parameters as a value, for <see cref="Impact.Resolve(Ball, in Vector3d, in Vector3d, in Vector3d, in ImpactBody, in ContactProperties)"/>.</summary>
        public ContactProperties Contact { get; }

        /// <summary>A short name for reports.</summary>
        public string Name { get; }

        /// <summary>
        /// Hard court after Cross (2020, Sports Eng. 23:9, as transcribed in docs/references.md section 5):
        /// e_y = 0.95 - 0.005 theta1, mu 0.73, e_x 0.1, D = 3e-4 v1 m.
        /// </summary>
        public static Surface Hard { get; } = new Surface("hard", 0.95, 0.005, 0.73, 0.1, 0, 3e-4);

        /// <summary>
        /// Clay: mu 0.80 and normal COR 0.85 (court chart, Tennis Industry magazine; Cross gives mu about 0.8),
        /// e_x 0.1 (Cross: 0.10-0.17), D 4 mm (Cross: about 4 mm, up to 11 mm measured on clay).
        /// </summary>
        public static Surface Clay { get; } = new Surface("clay", 0.85, 0, 0.80, 0.1, 0.004, 0);

        /// <summary>
        /// Grass: mu 0.60 and normal COR 0.60 (court chart, Tennis Industry magazine; Cross: mu 0.53-0.6,
        /// COR 0.6-0.75), e_x 0.1 (Cross: 0.10-0.17), D 4 mm (Cross: about 4 mm).
        /// </summary>
        public static Surface Grass { get; } = new Surface("grass", 0.60, 0, 0.60, 0.1, 0.004, 0);

        /// <summary>
        /// An ideal for tests: perfectly elastic (e_y = 1), no friction, no force offset. The tangential
        /// velocity and the spin pass through the bounce unchanged; only the normal velocity reverses.
        /// </summary>
        public static Surface Frictionless { get; } = new Surface("frictionless", 1, 0, 0, 0, 0, 0);

        /// <summary>The three court presets: hard, clay, grass.</summary>
        internal static Surface[] Courts => new[] { Hard, Clay, Grass };

        /// <summary>Every preset, the courts and <see cref="Frictionless"/>.</summary>
        internal static Surface[] All => new[] { Hard, Clay, Grass, Frictionless };

        /// <summary>The preset called <paramref name="name"/> (case-insensitive; surrounding spaces ignored): hard, clay, grass or frictionless.</summary>
        /// <param name="name">A preset name.</param>
        /// <exception cref="ArgumentException">The name is unknown; the message lists the known names.</exception>
        public static Surface FromName(string name)
        {
            foreach (Surface surface in All)
            {
                if (NameLookup.Matches(surface.Name, name))
                {
                    return surface;
                }
            }

            throw new ArgumentException($"surface must be one of hard, clay, grass, frictionless; got '{name ?? "null"}'.", nameof(name));
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"Surface({Name}: e_y={Contact.NormalRestitution:R}-{Contact.NormalRestitutionPerDegree:R}*theta, mu={Contact.Friction:R}, " +
            $"e_x={Contact.TangentialRestitution:R}, D={Contact.ForceOffset:R}+{Contact.ForceOffsetPerSpeed:R}*v)";
    }
}
