using System;

namespace MagnusBall.Contact.Swings
{
    /// <summary>
    /// A tennis racket swing at the moment of impact: head speed and path, face tilt and turn, and where on the
    /// strings the ball is hit (through the apparent coefficient of restitution there). Turns an incoming ball into
    /// a launch with <see cref="Impact"/>'s law. Immutable; <see cref="Hit"/> allocates nothing.
    /// </summary>
    /// <remarks>
    /// <para><b>Source.</b> Brody, Cross &amp; Lindsey, "The Physics and Technology of Tennis" (2002), ch. 11, as summarised
    /// by the USRSA: v_out = ACOR v_in + (1 + ACOR) v_racket along the face normal, with ACOR about 0.45 at the centre
    /// of the strings, 0.10 near the tip and 0.50 near the throat (<see cref="CentreRestitution"/>,
    /// <see cref="TipRestitution"/>, <see cref="ThroatRestitution"/>); a 120 mph serve needs about 83 mph of racket
    /// speed at the centre.</para>
    /// <para><b>Model.</b> The racket is a free body (a hand-held racket: the hand exerts little impulse during the
    /// ~5 ms impact) whose face responds at the impact point like a point mass M. The ball bounces off the string
    /// bed with the normal COR <see cref="StringBedRestitution"/> (0.85, an assumption: not traced to a measurement);
    /// M follows from the ACOR, M = m (1 + ACOR)/(e - ACOR), so the normal law is Brody's formula exactly
    /// (M = 0.21 kg at the centre for a 57 g ball). Along the face the ball slides or grips as in Cross's bounce, with
    /// friction <see cref="StringFriction"/> (0.4, an assumption: it makes every impact within 61 degrees of the
    /// normal grip, and Lindsey (Tennis Warehouse University, 2012) reports that strings bite the ball in every impact
    /// within 50 degrees) and no recoil of the slip (e_x = 0: the ball leaves rolling on the strings). The same
    /// effective mass acts along the face: string snap-back and the racket's rotation about its long axis are not
    /// modelled. A clamped racket (<see cref="Clamped"/>) has infinite effective mass. Cross &amp; Lindsey (Tennis
    /// Warehouse University, 2011) measured about 30 % less spin from a hand-held racket than from a clamped one for balls
    /// arriving with backspin at about 23 m/s, 40 degrees from the normal (the incoming spin not given); with the
    /// -3820 rpm of Lindsey's clamped-racket table ("String Movement and Spin") this model gives 29.6-33.2 % less at the
    /// centre (22.7-24.7 % for -3000 rpm), and the clamped racket's 1649 rpm lies inside that table's 1207-1803 rpm over 14
    /// string beds. For a ball arriving without spin it gives 8.9 % less for a gripping impact at the centre and 21.6 % less for
    /// a sliding one (19.5 % and 40.5 % near the tip). The racket's twist about its long axis, which Lindsey (2011) found
    /// changes the spin with the impact point, is not modelled (docs/impacts.md).</para>
    /// <para><b>Geometry.</b> In a <see cref="LaunchFrame"/> (up, forward toward the target, side = up x forward): the
    /// racket head moves along Direction(pathElevation, azimuth) and the face normal points along
    /// Direction(faceTilt, azimuth + faceTurn). A path that rises more steeply than the face is tilted (low to high)
    /// brushes up the back of the ball: topspin. A face tilted up more than the path (an open face) gives backspin
    /// (slice). A face turned away from the path gives sidespin.</para>
    /// </remarks>
    public readonly struct RacketSwing
    {
        /// <summary>ACOR at the centre of the strings (USRSA summary of Brody, Cross &amp; Lindsey ch. 11).</summary>
        public const double CentreRestitution = 0.45;

        /// <summary>ACOR near the tip (same source).</summary>
        public const double TipRestitution = 0.10;

        /// <summary>ACOR near the throat (same source).</summary>
        public const double ThroatRestitution = 0.50;

        /// <summary>The ball's normal COR on the string bed of a rigidly held racket: 0.85, an assumption (not traced to a measurement).</summary>
        internal const double StringBedRestitution = 0.85;

        /// <summary>Sliding friction between ball and strings: 0.4, an assumption (see the remarks).</summary>
        internal const double StringFriction = 0.4;

        /// <summary>Creates a swing.</summary>
        /// <param name="speed">Racket speed at the impact point, m/s; finite and &gt; 0.</param>
        /// <param name="pathElevationDegrees">The head's path above the horizontal, degrees, in [-80, 80] (positive: low to high).</param>
        /// <param name="faceTiltDegrees">The face normal's elevation, degrees, in [-80, 80] (positive: open, negative: closed).</param>
        /// <param name="apparentRestitution">The ACOR at the impact point; in [0, <see cref="StringBedRestitution"/>).</param>
        /// <param name="azimuthDegrees">The path's azimuth from the frame's forward toward its side, degrees; in [-90, 90].</param>
        /// <param name="faceTurnDegrees">The face normal's azimuth relative to the path, degrees; in [-60, 60].</param>
        /// <param name="clamped">True for a head-clamped racket (infinite effective mass, normal COR <see cref="StringBedRestitution"/>) instead of a hand-held one.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public RacketSwing(
            double speed, double pathElevationDegrees, double faceTiltDegrees, double apparentRestitution = CentreRestitution,
            double azimuthDegrees = 0, double faceTurnDegrees = 0, bool clamped = false)
        {
            Speed = Require.Positive(speed, nameof(speed));
            PathElevationDegrees = Require.InRange(pathElevationDegrees, -80, 80, nameof(pathElevationDegrees));
            FaceTiltDegrees = Require.InRange(faceTiltDegrees, -80, 80, nameof(faceTiltDegrees));
            if (!double.IsFinite(apparentRestitution) || apparentRestitution < 0 || apparentRestitution >= StringBedRestitution)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(apparentRestitution), apparentRestitution,
                    $"apparentRestitution must be in [0, {Require.Format(StringBedRestitution)}) (the string bed's own COR); got {Require.Format(apparentRestitution)}.");
            }

            ApparentRestitution = apparentRestitution;
            AzimuthDegrees = Require.InRange(azimuthDegrees, -90, 90, nameof(azimuthDegrees));
            FaceTurnDegrees = Require.InRange(faceTurnDegrees, -60, 60, nameof(faceTurnDegrees));
            Clamped = clamped;
        }

        /// <summary>Racket speed at the impact point, m/s.</summary>
        public double Speed { get; }

        /// <summary>The head's path above the horizontal, degrees.</summary>
        public double PathElevationDegrees { get; }

        /// <summary>The face normal's elevation, degrees (positive: open).</summary>
        public double FaceTiltDegrees { get; }

        /// <summary>The apparent COR at the impact point.</summary>
        public double ApparentRestitution { get; }

        /// <summary>The path's azimuth toward the frame's side, degrees.</summary>
        public double AzimuthDegrees { get; }

        /// <summary>The face normal's azimuth relative to the path, degrees.</summary>
        public double FaceTurnDegrees { get; }

        /// <summary>True for a head-clamped racket (infinite effective mass).</summary>
        internal bool Clamped { get; }

        /// <summary>A copy with another face tilt and azimuth (used by <c>Queries.SwingAim</c>).</summary>
        /// <param name="faceTiltDegrees">Face tilt, degrees, in [-80, 80].</param>
        /// <param name="azimuthDegrees">Azimuth, degrees, in [-90, 90].</param>
        public RacketSwing WithFace(double faceTiltDegrees, double azimuthDegrees) =>
            new RacketSwing(Speed, PathElevationDegrees, faceTiltDegrees, ApparentRestitution, azimuthDegrees, FaceTurnDegrees, Clamped);

        /// <summary>The racket's effective mass at the impact point for <paramref name="ball"/>: m (1 + ACOR)/(e - ACOR), kg (infinite when clamped).</summary>
        /// <param name="ball">The ball; not null.</param>
        internal double EffectiveMass(Ball ball)
        {
            Require.NotNull(ball, nameof(ball));
            return Clamped ? double.PositiveInfinity : ball.Mass * (1 + ApparentRestitution) / (StringBedRestitution - ApparentRestitution);
        }

        /// <summary>The contact parameters of ball on strings: e <see cref="StringBedRestitution"/>, mu <see cref="StringFriction"/>, e_x 0, no offset.</summary>
        internal static ContactProperties Strings => new ContactProperties(StringBedRestitution, StringFriction);

        /// <summary>The head's unit velocity direction in <paramref name="frame"/>.</summary>
        /// <param name="frame">The launch frame.</param>
        internal Vector3d PathDirection(in LaunchFrame frame) =>
            frame.Direction(PathElevationDegrees * SwingGeometry.Degree, AzimuthDegrees * SwingGeometry.Degree);

        /// <summary>The face's unit normal (toward the ball) in <paramref name="frame"/>.</summary>
        /// <param name="frame">The launch frame.</param>
        internal Vector3d FaceNormal(in LaunchFrame frame) =>
            frame.Direction(FaceTiltDegrees * SwingGeometry.Degree, (AzimuthDegrees + FaceTurnDegrees) * SwingGeometry.Degree);

        /// <summary>
        /// The launch this swing gives a ball arriving at <paramref name="position"/> with <paramref name="incomingVelocity"/>
        /// and <paramref name="incomingSpin"/> (zero for a serve's toss at its apex).
        /// </summary>
        /// <param name="ball">The ball; not null.</param>
        /// <param name="frame">Up, forward (toward the target) and side; not the default frame.</param>
        /// <param name="position">The ball's centre at impact, m; finite.</param>
        /// <param name="incomingVelocity">The ball's velocity just before the impact, m/s; finite.</param>
        /// <param name="incomingSpin">The ball's angular velocity just before the impact, rad/s; finite.</param>
        /// <returns>The launch; <see cref="SwingLaunch.IsHit"/> is false when the ball was not approaching the face.</returns>
        /// <exception cref="ArgumentException">An argument is null, not finite, or the frame is the default; the message names it.</exception>
        /// <exception cref="InvalidOperationException">This RacketSwing is the default value (not built by a constructor).</exception>
        public SwingLaunch Hit(Ball ball, in LaunchFrame frame, in Vector3d position, in Vector3d incomingVelocity, in Vector3d incomingSpin)
        {
            SwingGeometry.RequireBuilt(Speed, nameof(RacketSwing));
            Require.NotNull(ball, nameof(ball));
            SwingGeometry.RequireFrame(frame, nameof(frame));
            Require.Finite(position, nameof(position));
            Require.Finite(incomingVelocity, nameof(incomingVelocity));
            Require.Finite(incomingSpin, nameof(incomingSpin));
            var body = ImpactBody.Moving(PathDirection(frame) * Speed, FaceNormal(frame), EffectiveMass(ball));
            ImpactOutcome impact = Impact.Resolve(ball, position, incomingVelocity, incomingSpin, body, Strings);
            return new SwingLaunch(impact, frame);
        }

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant(
            $"RacketSwing({Speed:F2} m/s, path {PathElevationDegrees:F1} deg, face {FaceTiltDegrees:F2} deg, ACOR {ApparentRestitution:F2}, azimuth {AzimuthDegrees:F2} deg, turn {FaceTurnDegrees:F1} deg{(Clamped ? ", clamped" : string.Empty)})");
    }
}
