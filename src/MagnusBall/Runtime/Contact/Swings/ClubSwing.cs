using System;

namespace MagnusBall.Contact.Swings
{
    /// <summary>
    /// A golf club at impact, as a launch monitor describes it: club speed, dynamic loft, attack angle, face angle and
    /// club path, with the head's mass and the face's COR. Turns a ball at rest into ball speed, launch angle and
    /// direction, spin rate and spin axis with <see cref="Impact"/>'s law. Immutable; <see cref="Hit"/> allocates nothing.
    /// </summary>
    /// <remarks>
    /// <para><b>Geometry (the D-plane).</b> In a <see cref="LaunchFrame"/> (up, forward along the target line, side =
    /// up x forward) the head moves along Direction(attack angle, club path) and the face normal points along
    /// Direction(dynamic loft, face angle). The spin loft is the angle between the two (dynamic loft - attack angle when
    /// path and face agree). Friction acts along the face in the plane of the two vectors, so the ball launches in that
    /// plane (the D-plane) and spins about the axis perpendicular to it: the spin axis tilts when face and path differ.</para>
    /// <para><b>Speed.</b> A square, centred hit with no spin loft gives the smash factor bound (1 + e)/(1 + m/M): 1.488 for
    /// e = 0.83 (the USGA's COR limit 0.822 plus its 0.008 test tolerance), a 45.93 g ball and a 200 g head. Loft takes
    /// away normal speed (cos of the spin loft) and gives the ball a little speed along the face.</para>
    /// <para><b>Model assumptions.</b> The head is a free body (the shaft adds nothing during the ~0.5 ms contact): a point
    /// mass <see cref="HeadMass"/> at the impact point (the first constructor), or a rigid <see cref="ClubHead"/> that turns
    /// about its centre of gravity (the second: the gear effect), a rigid face (no face flex beyond the COR), friction
    /// <see cref="Friction"/> (default 0.4: an assumption, not traced to a measurement) and no recoil of the slip (e_x = 0).
    /// With these, a lofted ball grips and leaves rolling on the face: against the tour averages at the published launch
    /// angles, the ball speed is within 3 % for the driver and the 7-iron, the spin 50 % high for the driver (40 % high
    /// with <see cref="ClubHead.MeasuredDriver"/>, 18-55 % over that head's input range) and 25 % low for the 7-iron (docs/impacts.md).</para>
    /// </remarks>
    public readonly struct ClubSwing
    {
        /// <summary>The face's COR: 0.83, the USGA's limit 0.822 plus its 0.008 test tolerance.</summary>
        internal const double UsgaLimitRestitution = 0.83;

        /// <summary>A driver head's mass, kg (200 g).</summary>
        internal const double DriverHeadMass = 0.200;

        /// <summary>Creates a club delivery.</summary>
        /// <param name="speed">Club head speed, m/s; finite and &gt; 0.</param>
        /// <param name="dynamicLoftDegrees">Dynamic loft (the face normal's elevation at impact), degrees, in [-10, 80].</param>
        /// <param name="attackAngleDegrees">Attack angle (the head's path elevation; negative: hitting down), degrees, in [-45, 45].</param>
        /// <param name="faceAngleDegrees">Face angle toward the frame's side, degrees, in [-45, 45].</param>
        /// <param name="clubPathDegrees">Club path toward the frame's side, degrees, in [-45, 45].</param>
        /// <param name="headMass">The head's effective mass at the impact point, kg; finite and &gt;= 1e-6 (a milligram).</param>
        /// <param name="restitution">The ball's normal COR on the face; in [0, 1].</param>
        /// <param name="friction">Sliding friction ball-face; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public ClubSwing(
            double speed, double dynamicLoftDegrees, double attackAngleDegrees, double faceAngleDegrees = 0, double clubPathDegrees = 0,
            double headMass = DriverHeadMass, double restitution = UsgaLimitRestitution, double friction = 0.4)
        {
            Speed = Require.Positive(speed, nameof(speed));
            DynamicLoftDegrees = Require.InRange(dynamicLoftDegrees, -10, 80, nameof(dynamicLoftDegrees));
            AttackAngleDegrees = Require.InRange(attackAngleDegrees, -45, 45, nameof(attackAngleDegrees));
            FaceAngleDegrees = Require.InRange(faceAngleDegrees, -45, 45, nameof(faceAngleDegrees));
            ClubPathDegrees = Require.InRange(clubPathDegrees, -45, 45, nameof(clubPathDegrees));
            Head = new ClubHead(SwingGeometry.RequireBodyMass(headMass, nameof(headMass)), pointMass: true);
            Restitution = Require.InRange(restitution, 0, 1, nameof(restitution));
            Friction = Require.NonNegative(friction, nameof(friction));
        }

        /// <summary>Creates a club delivery with a rigid head that rotates about its centre of gravity during the impact.</summary>
        /// <param name="speed">Club head speed (of the impact point), m/s; finite and &gt; 0.</param>
        /// <param name="dynamicLoftDegrees">Dynamic loft, degrees, in [-10, 80].</param>
        /// <param name="attackAngleDegrees">Attack angle, degrees, in [-45, 45].</param>
        /// <param name="faceAngleDegrees">Face angle toward the frame's side, degrees, in [-45, 45].</param>
        /// <param name="clubPathDegrees">Club path toward the frame's side, degrees, in [-45, 45].</param>
        /// <param name="head">The head (mass, centre of gravity, moments of inertia); not the default value.</param>
        /// <param name="restitution">The ball's normal COR on the face; in [0, 1].</param>
        /// <param name="friction">Sliding friction ball-face; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public ClubSwing(
            double speed, double dynamicLoftDegrees, double attackAngleDegrees, double faceAngleDegrees, double clubPathDegrees, ClubHead head,
            double restitution = UsgaLimitRestitution, double friction = 0.4)
            : this(speed, dynamicLoftDegrees, attackAngleDegrees, faceAngleDegrees, clubPathDegrees, DriverHeadMass, restitution, friction)
        {
            if (!(head.Mass > 0))
            {
                throw new ArgumentException("head must be built by a ClubHead constructor (mass > 0 kg); got the default value.", nameof(head));
            }

            Head = head;
        }

        /// <summary>The head: its mass and, for a rigid head, its centre of gravity and moments of inertia.</summary>
        public ClubHead Head { get; }

        /// <summary>Club head speed, m/s.</summary>
        public double Speed { get; }

        /// <summary>Dynamic loft, degrees.</summary>
        public double DynamicLoftDegrees { get; }

        /// <summary>Attack angle, degrees (negative: down).</summary>
        public double AttackAngleDegrees { get; }

        /// <summary>Face angle toward the frame's side, degrees.</summary>
        public double FaceAngleDegrees { get; }

        /// <summary>Club path toward the frame's side, degrees.</summary>
        public double ClubPathDegrees { get; }

        /// <summary>Head mass, kg.</summary>
        internal double HeadMass => Head.Mass;

        /// <summary>The face's COR.</summary>
        internal double Restitution { get; }

        /// <summary>Friction ball-face.</summary>
        internal double Friction { get; }

        /// <summary>The spin loft: the 3D angle between the head's path and the face normal, degrees (dynamic loft - attack angle when face and path agree).</summary>
        internal double SpinLoftDegrees
        {
            get
            {
                var frame = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);
                double c = Vector3d.Dot(PathDirection(frame), FaceNormal(frame));
                c = Math.Max(-1, Math.Min(1, c));
                // acos(c) as atan2(sqrt(1 - c^2), c): the library's own deterministic atan2 (docs/determinism.md).
                return PortableMath.Atan2(Math.Sqrt((1 - c) * (1 + c)), c) * (180 / Math.PI);
            }
        }

        /// <summary>
        /// The smash factor bound (1 + e)/(1 + m/M) of a square, centred hit with no spin loft (for a rigid head: an impact on
        /// the CG's projection, <see cref="ClubHead.ImpactHeight"/> = 0, where the normal force passes through the CG).
        /// </summary>
        /// <param name="ball">The ball; not null.</param>
        internal double SmashFactorBound(Ball ball)
        {
            Require.NotNull(ball, nameof(ball));
            return (1 + Restitution) / (1 + ball.Mass / HeadMass);
        }

        /// <summary>The head's unit velocity direction in <paramref name="frame"/>.</summary>
        /// <param name="frame">The launch frame.</param>
        internal Vector3d PathDirection(in LaunchFrame frame) =>
            frame.Direction(AttackAngleDegrees * SwingGeometry.Degree, ClubPathDegrees * SwingGeometry.Degree);

        /// <summary>The face's unit normal in <paramref name="frame"/>.</summary>
        /// <param name="frame">The launch frame.</param>
        internal Vector3d FaceNormal(in LaunchFrame frame) =>
            frame.Direction(DynamicLoftDegrees * SwingGeometry.Degree, FaceAngleDegrees * SwingGeometry.Degree);

        /// <summary>The launch of a ball at rest at <paramref name="position"/> (on a tee or the turf).</summary>
        /// <param name="ball">The ball; not null.</param>
        /// <param name="frame">Up, forward along the target line, side; not the default frame.</param>
        /// <param name="position">The ball's centre, m; finite.</param>
        /// <exception cref="ArgumentException">An argument is null, not finite, the frame is the default, or the ball is over 1e12 times the
        /// head's mass; the message names it.</exception>
        /// <exception cref="InvalidOperationException">This ClubSwing is the default value (not built by a constructor).</exception>
        public SwingLaunch Hit(Ball ball, in LaunchFrame frame, in Vector3d position)
        {
            SwingGeometry.RequireBuilt(Speed, nameof(ClubSwing));
            Require.NotNull(ball, nameof(ball));
            SwingGeometry.RequireMassRatio(ball, HeadMass, "head");
            SwingGeometry.RequireFrame(frame, nameof(frame));
            Require.Finite(position, nameof(position));
            Vector3d normal = FaceNormal(frame);
            var body = ImpactBody.Moving(PathDirection(frame) * Speed, normal, HeadMass);
            var contact = new ContactProperties(Restitution, Friction);
            if (Head.IsPointMass)
            {
                return new SwingLaunch(Impact.Resolve(ball, position, Vector3d.Zero, Vector3d.Zero, body, contact), frame);
            }

            RigidBodyInertia inertia = Head.Inertia(normal, SwingGeometry.UpAcross(frame, normal));
            return new SwingLaunch(Impact.Resolve(ball, position, Vector3d.Zero, Vector3d.Zero, body, inertia, contact), frame);
        }

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant(
            $"ClubSwing({Speed:F2} m/s, loft {DynamicLoftDegrees:F1}, attack {AttackAngleDegrees:F1}, face {FaceAngleDegrees:F1}, path {ClubPathDegrees:F1} deg, head {HeadMass:R} kg{(Head.IsPointMass ? "" : " rigid")}, e {Restitution:R})");
    }
}
