using System;

namespace MagnusBall.Contact.Swings
{
    /// <summary>
    /// A baseball bat at impact: bat speed at the impact point, swing direction, undercut (how far the bat's centre
    /// passes below the ball's) and the collision efficiency q of the bat at that point. Turns a pitch into a batted
    /// ball with <see cref="Impact"/>'s law. Immutable; <see cref="Hit"/> allocates nothing.
    /// </summary>
    /// <remarks>
    /// <para><b>Source.</b> Nathan (2003, "Characterizing the performance of baseball bats", Am. J. Phys. 71:134): the
    /// batted-ball speed of a head-on collision is q v_pitch + (1 + q) v_bat with the collision efficiency q, about 0.2
    /// for a wood bat at its sweet spot (<see cref="WoodCollisionEfficiency"/>): a 90 mph pitch and an 80 mph bat give
    /// about 114 mph. q is the apparent COR of Brody's tennis formula: q = (e - m/M)/(1 + m/M).</para>
    /// <para><b>Model.</b> The bat is a cylinder of radius <see cref="BarrelRadius"/> whose axis is horizontal and
    /// across the swing direction; the contact normal runs along the line of centres, which tilts up by
    /// asin(undercut/(R_ball + R_bat)) when the bat passes below the ball's centre. The bat responds at the impact
    /// point like a point mass M = m (1 + q)/(e - q), the same along the normal and along the surface, with the ball-bat
    /// COR <see cref="Restitution"/> (default 0.5: an assumption, not traced here; it puts M at 0.58 kg for q = 0.2), and
    /// friction <see cref="Friction"/> (default 0.5: an assumption, not traced) with no recoil of the slip. Undercut
    /// turns part of the normal impulse into a tangential one: backspin grows and the launch rises; overcut gives topspin.</para>
    /// </remarks>
    public readonly struct BatSwing
    {
        /// <summary>Collision efficiency of a wood bat at its sweet spot, about 0.2 (Nathan 2003).</summary>
        internal const double WoodCollisionEfficiency = 0.2;

        /// <summary>A barrel radius, m: 2.625 in diameter (0.0333 m radius).</summary>
        internal const double BarrelRadius = 0.0333375;

        /// <summary>Creates a bat swing.</summary>
        /// <param name="speed">Bat speed at the impact point, m/s; finite and &gt; 0.</param>
        /// <param name="undercut">Distance the bat's centre passes below the ball's centre, m (negative: above); within +-(ball radius + barrel radius).</param>
        /// <param name="swingElevationDegrees">The bat's path above the horizontal, degrees, in [-45, 45].</param>
        /// <param name="azimuthDegrees">The bat's path azimuth toward the frame's side, degrees, in [-90, 90].</param>
        /// <param name="collisionEfficiency">q at the impact point; in [0, restitution).</param>
        /// <param name="restitution">Ball-bat normal COR; in (0, 1].</param>
        /// <param name="friction">Ball-bat sliding friction; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public BatSwing(
            double speed, double undercut = 0, double swingElevationDegrees = 0, double azimuthDegrees = 0,
            double collisionEfficiency = WoodCollisionEfficiency, double restitution = 0.5, double friction = 0.5)
        {
            Speed = Require.Positive(speed, nameof(speed));
            Undercut = Require.Finite(undercut, nameof(undercut));
            SwingElevationDegrees = Require.InRange(swingElevationDegrees, -45, 45, nameof(swingElevationDegrees));
            AzimuthDegrees = Require.InRange(azimuthDegrees, -90, 90, nameof(azimuthDegrees));
            if (!(restitution > 0 && restitution <= 1))
            {
                throw new ArgumentOutOfRangeException(nameof(restitution), restitution, $"restitution must be in (0, 1]; got {Require.Format(restitution)}.");
            }

            Restitution = restitution;
            if (!double.IsFinite(collisionEfficiency) || collisionEfficiency < 0 || collisionEfficiency >= restitution)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(collisionEfficiency), collisionEfficiency,
                    $"collisionEfficiency must be in [0, {Require.Format(restitution)}) (below the ball-bat COR); got {Require.Format(collisionEfficiency)}.");
            }

            CollisionEfficiency = collisionEfficiency;
            Friction = Require.NonNegative(friction, nameof(friction));
        }

        /// <summary>Bat speed at the impact point, m/s.</summary>
        public double Speed { get; }

        /// <summary>The bat centre's offset below the ball's centre, m.</summary>
        public double Undercut { get; }

        /// <summary>The bat's path above the horizontal, degrees.</summary>
        public double SwingElevationDegrees { get; }

        /// <summary>The bat's path azimuth toward the frame's side, degrees.</summary>
        public double AzimuthDegrees { get; }

        /// <summary>Collision efficiency q.</summary>
        internal double CollisionEfficiency { get; }

        /// <summary>Ball-bat normal COR.</summary>
        internal double Restitution { get; }

        /// <summary>Ball-bat sliding friction.</summary>
        internal double Friction { get; }

        /// <summary>The bat's effective mass at the impact point, m (1 + q)/(e - q), kg.</summary>
        /// <param name="ball">The ball; not null.</param>
        internal double EffectiveMass(Ball ball)
        {
            Require.NotNull(ball, nameof(ball));
            return ball.Mass * (1 + CollisionEfficiency) / (Restitution - CollisionEfficiency);
        }

        /// <summary>The launch of a pitch arriving at <paramref name="position"/> with <paramref name="pitchVelocity"/> and <paramref name="pitchSpin"/>.</summary>
        /// <param name="ball">The ball; not null.</param>
        /// <param name="frame">Up, forward (the direction the bat swings toward: the field), side; not the default frame.</param>
        /// <param name="position">The ball's centre at impact, m; finite.</param>
        /// <param name="pitchVelocity">The pitch's velocity at impact, m/s; finite.</param>
        /// <param name="pitchSpin">The pitch's angular velocity, rad/s; finite.</param>
        /// <exception cref="ArgumentException">An argument is null, not finite, the frame is the default, or the undercut exceeds the sum of the radii.</exception>
        /// <exception cref="InvalidOperationException">This BatSwing is the default value (not built by a constructor).</exception>
        public SwingLaunch Hit(Ball ball, in LaunchFrame frame, in Vector3d position, in Vector3d pitchVelocity, in Vector3d pitchSpin)
        {
            SwingGeometry.RequireBuilt(Speed, nameof(BatSwing));
            Require.NotNull(ball, nameof(ball));
            SwingGeometry.RequireFrame(frame, nameof(frame));
            Require.Finite(position, nameof(position));
            Require.Finite(pitchVelocity, nameof(pitchVelocity));
            Require.Finite(pitchSpin, nameof(pitchSpin));
            double reach = ball.Radius + BarrelRadius;
            if (!(Math.Abs(Undercut) < reach))
            {
                throw new ArgumentException(
                    $"undercut must be within +-{Require.Format(reach)} m (ball radius + barrel radius) for the bat to touch the ball; got {Require.Format(Undercut)} m.", nameof(ball));
            }

            Vector3d d = frame.Direction(SwingElevationDegrees * SwingGeometry.Degree, AzimuthDegrees * SwingGeometry.Degree);
            Vector3d lift = SwingGeometry.UpAcross(frame, d);
            double sine = Undercut / reach;
            Vector3d normal = d * Math.Sqrt(1 - sine * sine) + lift * sine;
            var body = ImpactBody.Moving(d * Speed, normal, EffectiveMass(ball));
            ImpactOutcome impact = Impact.Resolve(ball, position, pitchVelocity, pitchSpin, body, new ContactProperties(Restitution, Friction));
            return new SwingLaunch(impact, frame);
        }

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant(
            $"BatSwing({Speed:F2} m/s, undercut {Undercut * 1000:F1} mm, elevation {SwingElevationDegrees:F1} deg, q {CollisionEfficiency:R}, e {Restitution:R})");
    }
}
