using System;

namespace MagnusBall.Contact.Swings
{
    /// <summary>
    /// A kick: foot speed, how far off the ball's centre the foot strikes, and the foot-ball friction. Turns a ball
    /// at rest into a launch with speed and curl-producing spin with <see cref="Impact"/>'s law. Immutable;
    /// <see cref="Hit"/> allocates nothing.
    /// </summary>
    /// <remarks>
    /// <para><b>Source.</b> Asai, Carré, Akatsuka &amp; Haake (2002, "The curve kick of a football I: impact with the
    /// foot", Sports Engineering 5:183-192), a finite-element model checked against high-speed video: the spin grows
    /// with the offset between the foot and the ball's axis and with the friction coefficient, the offset matters more
    /// than the friction, friction from 0 to 1 adds at most 13 rad/s of spin, the offset that gives the most spin is
    /// around 100 mm, and ball speed trades off against spin.</para>
    /// <para><b>Model.</b> The foot moves along Direction(elevation, azimuth) and touches the ball at a point
    /// <see cref="Offset"/> to the side of the ball's centre line (positive: toward -side, so the ball is pushed toward
    /// +side); the foot's surface is tangent to the ball there, so the contact normal is tilted from the path by
    /// asin(offset/R). The foot is a rigid point mass <see cref="FootMass"/> (default 1.5 kg: an assumption, not traced)
    /// with the ball-foot COR <see cref="Restitution"/> (default 0.5: an assumption, not traced; together they send a
    /// centred kick off at 1.16 times the foot speed). Unlike Asai's deforming ball, a rigid contact makes no spin
    /// without friction: here all the spin comes from friction (docs/impacts.md compares the two). Over the frictions
    /// measured for real balls against leather (0.37-0.63 for nine balls; "The Coefficient of Friction of Soccer Balls",
    /// Proceedings 2020, 49(1), 92), which the default 0.5 lies inside, the ball grips at offsets up to 80 mm and the
    /// spin there does not depend on the friction (20-30 m/s); from 85 mm the impact begins to slide and it matters.</para>
    /// </remarks>
    public readonly struct KickSwing
    {
        /// <summary>Creates a kick.</summary>
        /// <param name="speed">Foot speed, m/s; finite and &gt; 0.</param>
        /// <param name="offset">Offset of the contact from the ball's centre line, m; |offset| below the ball's radius (checked at <see cref="Hit"/>).</param>
        /// <param name="friction">Foot-ball sliding friction; in [0, 2]. Default 0.5, inside the 0.37-0.63 measured for nine match balls against leather (see remarks).</param>
        /// <param name="elevationDegrees">The foot's path above the horizontal, degrees, in [-45, 60].</param>
        /// <param name="azimuthDegrees">The foot's path azimuth toward the frame's side, degrees, in [-90, 90].</param>
        /// <param name="footMass">The foot's effective mass, kg; finite and &gt;= 1e-6 (a milligram).</param>
        /// <param name="restitution">Ball-foot normal COR; in [0, 1].</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public KickSwing(
            double speed, double offset = 0, double friction = 0.5, double elevationDegrees = 0, double azimuthDegrees = 0,
            double footMass = 1.5, double restitution = 0.5)
        {
            Speed = Require.Positive(speed, nameof(speed));
            Offset = Require.Finite(offset, nameof(offset));
            Friction = Require.InRange(friction, 0, 2, nameof(friction));
            ElevationDegrees = Require.InRange(elevationDegrees, -45, 60, nameof(elevationDegrees));
            AzimuthDegrees = Require.InRange(azimuthDegrees, -90, 90, nameof(azimuthDegrees));
            FootMass = SwingGeometry.RequireBodyMass(footMass, nameof(footMass));
            Restitution = Require.InRange(restitution, 0, 1, nameof(restitution));
        }

        /// <summary>Foot speed, m/s.</summary>
        public double Speed { get; }

        /// <summary>Offset of the contact from the ball's centre line, m (positive: toward -side).</summary>
        public double Offset { get; }

        /// <summary>Foot-ball sliding friction.</summary>
        internal double Friction { get; }

        /// <summary>The foot's path above the horizontal, degrees.</summary>
        public double ElevationDegrees { get; }

        /// <summary>The foot's path azimuth toward the frame's side, degrees.</summary>
        public double AzimuthDegrees { get; }

        /// <summary>The foot's effective mass, kg.</summary>
        internal double FootMass { get; }

        /// <summary>Ball-foot normal COR.</summary>
        internal double Restitution { get; }

        /// <summary>The launch of a ball at rest at <paramref name="position"/>.</summary>
        /// <param name="ball">The ball; not null.</param>
        /// <param name="frame">Up, forward, side; not the default frame.</param>
        /// <param name="position">The ball's centre, m; finite.</param>
        /// <exception cref="ArgumentException">An argument is null, not finite, the frame is the default, |offset| is not below the ball's radius,
        /// or the ball is over 1e12 times the foot's mass.</exception>
        /// <exception cref="InvalidOperationException">This KickSwing is the default value (not built by a constructor).</exception>
        public SwingLaunch Hit(Ball ball, in LaunchFrame frame, in Vector3d position)
        {
            SwingGeometry.RequireBuilt(Speed, nameof(KickSwing));
            Require.NotNull(ball, nameof(ball));
            SwingGeometry.RequireMassRatio(ball, FootMass, "foot");
            SwingGeometry.RequireFrame(frame, nameof(frame));
            Require.Finite(position, nameof(position));
            if (!(Math.Abs(Offset) < ball.Radius))
            {
                throw new ArgumentException(
                    $"offset must be within +-{Require.Format(ball.Radius)} m (the ball's radius) for the foot to strike the ball; got {Require.Format(Offset)} m.", nameof(ball));
            }

            Vector3d d = frame.Direction(ElevationDegrees * SwingGeometry.Degree, AzimuthDegrees * SwingGeometry.Degree);
            Vector3d side = SwingGeometry.SideAcross(frame, d);
            double sine = Offset / ball.Radius;
            Vector3d normal = d * Math.Sqrt(1 - sine * sine) + side * sine;
            var body = ImpactBody.Moving(d * Speed, normal, FootMass);
            ImpactOutcome impact = Impact.Resolve(ball, position, Vector3d.Zero, Vector3d.Zero, body, new ContactProperties(Restitution, Friction));
            return new SwingLaunch(impact, frame);
        }

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant(
            $"KickSwing({Speed:F2} m/s, offset {Offset * 1000:F0} mm, mu {Friction:R}, elevation {ElevationDegrees:F1} deg, foot {FootMass:R} kg, e {Restitution:R})");
    }
}
