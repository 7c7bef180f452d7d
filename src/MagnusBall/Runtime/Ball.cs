using System;

namespace MagnusBall
{
    /// <summary>
    /// What a ball is, for flight: its mass, its radius and how its mass is spread (the moment-of-inertia
    /// factor alpha in I = alpha m r^2). Immutable and safe to share between threads.
    /// </summary>
    public sealed class Ball
    {
        /// <summary>Moment-of-inertia factor of a uniform solid sphere, 2/5.</summary>
        internal const double SolidSphereInertiaFactor = 0.4;

        /// <summary>Moment-of-inertia factor of a thin spherical shell, 2/3.</summary>
        public const double ThinShellInertiaFactor = 2.0 / 3.0;

        /// <summary>
        /// Creates a ball.
        /// </summary>
        /// <param name="mass">Mass, kg; finite and &gt; 0.</param>
        /// <param name="radius">Radius, m; finite and &gt; 0.</param>
        /// <param name="inertiaFactor">
        /// alpha in I = alpha m r^2; finite, in (0, 1]. 0.4 for a solid sphere, 2/3 for a thin shell,
        /// about 0.55 for a tennis ball (Cross 2002, a hollow shell of finite thickness).
        /// </param>
        /// <exception cref="ArgumentOutOfRangeException">A value is outside its range; the message names it.</exception>
        public Ball(double mass, double radius, double inertiaFactor = SolidSphereInertiaFactor)
        {
            Require.Positive(mass, nameof(mass));
            Require.Positive(radius, nameof(radius));
            if (!double.IsFinite(inertiaFactor) || inertiaFactor <= 0 || inertiaFactor > 1)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(inertiaFactor), inertiaFactor, $"inertiaFactor must be in (0, 1]; got {Require.Format(inertiaFactor)}.");
            }

            Mass = mass;
            Radius = radius;
            InertiaFactor = inertiaFactor;
        }

        /// <summary>Mass, kg.</summary>
        public double Mass { get; }

        /// <summary>Radius, m.</summary>
        public double Radius { get; }

        /// <summary>Moment-of-inertia factor alpha (I = alpha m r^2).</summary>
        public double InertiaFactor { get; }

        /// <summary>Cross-sectional area pi r^2, m^2.</summary>
        internal double CrossSectionalArea => Math.PI * Radius * Radius;

        /// <summary>Moment of inertia about a diameter, alpha m r^2, kg m^2.</summary>
        internal double MomentOfInertia => InertiaFactor * Mass * Radius * Radius;

        /// <summary>
        /// The library's one tennis ball: that of the seed thesis and of Cross (2011), 0.057 kg, 0.033 m, alpha 0.55
        /// (inside the ITF's 56.0-59.4 g and 6.54-6.86 cm). The tennis presets fly this ball.
        /// </summary>
        public static Ball Tennis { get; } = new Ball(0.057, 0.033, 0.55);

        /// <summary>
        /// The soccer ball of Javorova &amp; Ivanov (2018) as quoted by the thesis: 0.425 kg, 0.11 m, thin shell (for their
        /// free kicks; the <c>soccer</c> preset, <see cref="Presets.SportPresets.Soccer"/>, flies 0.43 kg, inside FIFA's 410-450 g).
        /// </summary>
        public static Ball Soccer { get; } = new Ball(0.425, 0.11, ThinShellInertiaFactor);

        /// <inheritdoc />
        public override string ToString() => $"Ball(m={Mass:R} kg, r={Radius:R} m, alpha={InertiaFactor:R})";
    }
}
