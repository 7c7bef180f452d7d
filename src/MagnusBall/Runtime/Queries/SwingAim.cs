// SwingAim: the swing inverses for AI players (the public calls) and their work budget. The shared solve is in
// SwingAim.Solve.cs, each swing's two angles in SwingAim.Families.cs.
using System;
using MagnusBall.Contact.Swings;

namespace MagnusBall.Queries
{
    /// <summary>
    /// The result of a <see cref="SwingAim"/> solve: the swing found (<typeparamref name="TSwing"/>: a
    /// <see cref="RacketSwing"/>, <see cref="ClubSwing"/>, <see cref="BatSwing"/> or <see cref="KickSwing"/>) and the
    /// launch it gives.
    /// </summary>
    /// <typeparam name="TSwing">The swing helper.</typeparam>
    public readonly struct SwingSolution<TSwing>
        where TSwing : struct
    {
        /// <summary>Creates a result.</summary>
        /// <param name="status">Solved or unreachable.</param>
        /// <param name="swing">The swing (the last one tried when unreachable).</param>
        /// <param name="launch">Its launch.</param>
        /// <param name="aim">The aim solver's launch for that swing's speed and spin.</param>
        /// <param name="iterations">Outer iterations used.</param>
        internal SwingSolution(AimStatus status, in TSwing swing, in SwingLaunch launch, in AimSolution aim, int iterations)
        {
            Status = status;
            Swing = swing;
            Launch = launch;
            Aim = aim;
            Iterations = iterations;
        }

        /// <summary>Solved, unreachable (the swing cannot send the ball there) or stopped at the work budget (<see cref="AimStatus.WorkLimitReached"/>).</summary>
        public AimStatus Status { get; }

        /// <summary>True when solved.</summary>
        public bool IsSolved => Status == AimStatus.Solved;

        /// <summary>The swing: the input's own parameters with the two the solve adjusts replaced (see each <see cref="SwingAim"/> method).</summary>
        public TSwing Swing { get; }

        /// <summary>The launch the swing gives, with its angles measured in the aim solver's frame (up, forward toward the target).</summary>
        public SwingLaunch Launch { get; }

        /// <summary>The aim solver's solution for the launch's speed and spin (its direction is the launch's to <see cref="SwingAim.AngleTolerance"/>).</summary>
        public AimSolution Aim { get; }

        /// <summary>Outer iterations (each one aim solve).</summary>
        public int Iterations { get; }

        /// <inheritdoc />
        public override string ToString() => $"SwingSolution({Status}, {Swing}, {Launch}, {Iterations} iterations)";
    }

    /// <summary>
    /// The inverse of the swing helpers, for AI players: the swing that sends the ball to a target. Built on
    /// <see cref="AimSolver"/>: the aim solver finds the launch direction that reaches the target for the launch's speed
    /// and spin, and two of the swing's angles are turned until the swing launches the ball in that direction.
    /// </summary>
    /// <remarks>
    /// <para>The player's speed (and the rest of the swing) is kept; two angles that set the launch's elevation and
    /// direction are solved: a racket's face tilt and azimuth, a club's dynamic loft and face angle (the path turned with
    /// the face), a bat's and a foot's path elevation and azimuth. The residual is the difference between the direction
    /// the aim solver finds for the launch's speed and spin (by effect) and the direction the swing launches in. It is
    /// driven to zero by Broyden's method, started from the 2 x 2 Jacobian of the launch angles by central differences
    /// of the swing alone (four impacts, no flights); the updates learn how the aim solver's answer moves with the
    /// launch speed and spin, and a step that makes the residual worse, leaves the swing's ranges or makes the target
    /// unreachable is halved (up to 12 times). Each residual costs one aim solve; it stops when the directions agree
    /// to <see cref="AngleTolerance"/>, after at most <see cref="MaximumIterations"/> steps. A target the swing cannot
    /// reach with its speed (too far, or only by leaving the angles' ranges) gives <see cref="AimStatus.Unreachable"/>.</para>
    /// <para>Holds its <see cref="AimSolver"/>, which is not thread-safe: one <see cref="SwingAim"/> per thread.</para>
    /// </remarks>
    public sealed partial class SwingAim
    {
        /// <summary>The launch direction agrees with the aim solver's to this, rad.</summary>
        internal const double AngleTolerance = 1e-9;

        /// <summary>The most outer iterations (aim solves) of one solve.</summary>
        internal const int MaximumIterations = 40;

        /// <summary>
        /// The aim solver's solution counts only when it passes this close to the target, m (its angle tolerance gives
        /// about 1e-7 m at tennis distances; a solver that returns its lower elevation limit can be farther). For a target
        /// below the ground (a point on the court while the ground plane is at the ball's centre), which the aim solver
        /// answers with the launch that comes down over it, the distance is measured along the ground: from the landing to
        /// the point over the target.
        /// </summary>
        internal const double MissTolerance = 1e-4;

        /// <summary>The default budget of one inverse call on an adaptive solver, in aim solves' budgets.</summary>
        internal const int DefaultSolvesOfWork = 3;

        /// <summary>
        /// The default budget of one inverse call on a fixed-step solver, in aim solves' budgets: its solves of a target below
        /// the ground (a court point with the ground at the ball's centre) take hundreds of trials each.
        /// </summary>
        internal const int DefaultFixedStepSolvesOfWork = 10;

        /// <summary>The largest budget of one inverse call.</summary>
        internal const long MaximumEvaluationsAllowed = 1_000_000_000_000;

        /// <summary>
        /// The residual must shrink to this part of what it was <see cref="StallIterations"/> accepted steps earlier; a
        /// Broyden run that converges shrinks it by orders of magnitude in that many steps, one toward a target beyond the
        /// swing's reach creeps along the edge of its reach and is called Unreachable.
        /// </summary>
        private const double StallRatio = 0.5;

        /// <summary>See <see cref="StallRatio"/>.</summary>
        private const int StallIterations = 2;

        /// <summary>
        /// A step whose first <see cref="EdgeTrials"/> trials (or more) are out of the aim solver's reach and whose accepted
        /// trial shrinks the residual by less than <see cref="EdgeProgress"/> ends the solve as Unreachable.
        /// </summary>
        private const int EdgeTrials = 2;

        /// <summary>See <see cref="EdgeTrials"/>.</summary>
        private const double EdgeProgress = 0.1;

        private const double DifferenceDegrees = 1e-4;
        private const int MaximumHalvings = 12;

        private static long Budget(AimSolver solver, long maximumEvaluations)
        {
            if (maximumEvaluations == 0)
            {
                return (solver.IsAdaptive ? DefaultSolvesOfWork : DefaultFixedStepSolvesOfWork) * solver.MaximumEvaluations;
            }

            long value = maximumEvaluations;
            if (value < AimSolver.MinimumEvaluationsPerSolve || value > MaximumEvaluationsAllowed)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(maximumEvaluations), value,
                    $"maximumEvaluations must be in [{AimSolver.MinimumEvaluationsPerSolve}, {MaximumEvaluationsAllowed}] model evaluations plus steps, or 0 for the default; got {value}.");
            }

            return value;
        }

        /// <summary>Creates the inverse on an aim solver; the swings hit the ball its model flies.</summary>
        /// <param name="solver">The aim solver (model, integrator, step, ground); not null.</param>
        /// <param name="maximumEvaluations">The work budget of one inverse call: model evaluations plus steps over all its aim solves, in [1,000, 1e12], or 0; past it the call returns <see cref="AimStatus.WorkLimitReached"/>. 0 (the default): 3 times the solver's budget per solve for an adaptive solver (60,000 for its default: about 11 ms of golf-preset work, where an ordinary inverse makes 2,000-5,000), 10 times for a fixed-step one (10,000,000 for its default).</param>
        /// <exception cref="ArgumentNullException"><paramref name="solver"/> is null.</exception>
        /// <exception cref="ArgumentException"><paramref name="maximumEvaluations"/> is out of range.</exception>
        public SwingAim(AimSolver solver, long maximumEvaluations = 0)
        {
            Solver = Require.NotNull(solver, nameof(solver));
            Ball = solver.Model.Ball;
            MaximumEvaluations = Budget(solver, maximumEvaluations);
        }

        /// <summary>Creates the inverse on an aim solver, naming the ball the swings hit (it must be the one the solver's model flies).</summary>
        /// <param name="solver">The aim solver (model, integrator, step, ground); not null.</param>
        /// <param name="ball">The ball the swings hit; not null, with the mass, radius and inertia factor of the solver's model's ball
        /// (the impact and the trial flights are of one ball).</param>
        /// <param name="maximumEvaluations">The work budget of one inverse call (see <see cref="SwingAim(AimSolver, long)"/>); 0: the default.</param>
        /// <exception cref="ArgumentNullException">An argument is null.</exception>
        /// <exception cref="ArgumentException"><paramref name="ball"/> is not the model's ball (a tennis ball hit and flown with a soccer model's aerodynamics), or <paramref name="maximumEvaluations"/> is out of range.</exception>
        public SwingAim(AimSolver solver, Ball ball, long maximumEvaluations = 0)
        {
            Solver = Require.NotNull(solver, nameof(solver));
            Ball = Require.NotNull(ball, nameof(ball));
            long budget = Budget(solver, maximumEvaluations);
            Ball flown = solver.Model.Ball;
            if (ball.Mass != flown.Mass || ball.Radius != flown.Radius || ball.InertiaFactor != flown.InertiaFactor)
            {
                throw new ArgumentException(
                    FormattableString.Invariant(
                        $"ball ({ball.Mass} kg, radius {ball.Radius} m, inertia factor {ball.InertiaFactor}) must be the ball the aim solver's model flies ") +
                    FormattableString.Invariant($"({flown.Mass} kg, radius {flown.Radius} m, inertia factor {flown.InertiaFactor}): the swing hits the ball its trials fly."),
                    nameof(ball));
            }

            MaximumEvaluations = budget;
        }

        /// <summary>The aim solver.</summary>
        internal AimSolver Solver { get; }

        /// <summary>The work budget of one inverse call (model evaluations plus steps over its aim solves).</summary>
        internal long MaximumEvaluations { get; }

        /// <summary>Model evaluations plus steps of the last inverse call.</summary>
        internal long LastWork { get; private set; }

        private bool _budgetReached;

        /// <summary>The ball.</summary>
        internal Ball Ball { get; }

        /// <summary>
        /// The face tilt and azimuth with which <paramref name="swing"/> (its speed, path, impact point and face turn kept)
        /// sends a ball arriving at <paramref name="position"/> through <paramref name="target"/> (for a target on the
        /// ground: lands there). The swing is oriented in <paramref name="frame"/>; the launch is compared with the aim
        /// solver's in the solver's frame (its up, forward toward the target).
        /// </summary>
        /// <param name="swing">The swing; its face tilt and azimuth are the starting guess.</param>
        /// <param name="frame">The frame the swing's angles are given in (its azimuth is from this frame's forward); not the default frame.</param>
        /// <param name="position">The ball's centre at impact, m; finite.</param>
        /// <param name="incomingVelocity">The ball's velocity before the impact, m/s; finite.</param>
        /// <param name="incomingSpin">The ball's angular velocity before the impact, rad/s; finite.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the position.</param>
        /// <param name="maximumAzimuthDegrees">The largest launch azimuth from the target direction the aim solver tries, degrees; in (0, 89].</param>
        /// <returns>The solved swing, or <see cref="AimStatus.Unreachable"/> when the swing cannot reach the target (never an exception for finite input).</returns>
        /// <exception cref="ArgumentException">An argument is not finite, the swing or frame is the default value, or the target is straight above or below the position; the message names it.</exception>
        public SwingSolution<RacketSwing> RacketFaceToReach(
            in RacketSwing swing, in LaunchFrame frame, in Vector3d position, in Vector3d incomingVelocity, in Vector3d incomingSpin, in Vector3d target,
            double maximumAzimuthDegrees = 45)
        {
            LaunchFrame aimFrame = Check(frame, position, target, maximumAzimuthDegrees);
            Require.Finite(incomingVelocity, nameof(incomingVelocity));
            Require.Finite(incomingSpin, nameof(incomingSpin));
            RequireBuilt(swing.Speed, nameof(swing), nameof(RacketSwing));
            var family = new RacketFamily(swing, frame, position, incomingVelocity, incomingSpin, Ball);
            return Solve<RacketSwing, RacketFamily>(ref family, aimFrame, swing.FaceTiltDegrees, swing.AzimuthDegrees, position, target, maximumAzimuthDegrees);
        }

        /// <summary>
        /// The dynamic loft and face angle with which the club delivery <paramref name="swing"/> (its speed, attack angle,
        /// face-to-path angle, head and face kept; the club path turns with the face) sends a ball at rest at
        /// <paramref name="position"/> through <paramref name="target"/> (for a target on the ground: carries there).
        /// The loft is the player's club choice and the face his aim: for a fixed club, aim with <see cref="AimSolver"/>
        /// on the speed instead.
        /// </summary>
        /// <param name="swing">The delivery; its dynamic loft and face angle are the starting guess.</param>
        /// <param name="frame">The frame the delivery's angles are given in (forward: the target line); not the default frame.</param>
        /// <param name="position">The ball's centre, m; finite.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the position.</param>
        /// <param name="maximumAzimuthDegrees">The largest launch azimuth from the target direction the aim solver tries, degrees; in (0, 89].</param>
        /// <returns>The solved delivery, or <see cref="AimStatus.Unreachable"/> (loft within [-10, 80] deg, face and path within +-45 deg).</returns>
        /// <exception cref="ArgumentException">An argument is not finite, the swing or frame is the default value, or the target is straight above or below the position; the message names it.</exception>
        public SwingSolution<ClubSwing> ClubFaceToReach(
            in ClubSwing swing, in LaunchFrame frame, in Vector3d position, in Vector3d target, double maximumAzimuthDegrees = 45)
        {
            LaunchFrame aimFrame = Check(frame, position, target, maximumAzimuthDegrees);
            RequireBuilt(swing.Speed, nameof(swing), nameof(ClubSwing));
            var family = new ClubFamily(swing, frame, position, Ball);
            return Solve<ClubSwing, ClubFamily>(ref family, aimFrame, swing.DynamicLoftDegrees, swing.FaceAngleDegrees, position, target, maximumAzimuthDegrees);
        }

        /// <summary>
        /// The swing elevation and azimuth with which <paramref name="swing"/> (its speed, undercut, collision efficiency,
        /// COR and friction kept) sends a pitch arriving at <paramref name="position"/> through <paramref name="target"/>
        /// (a point in the field: lands there).
        /// </summary>
        /// <param name="swing">The bat swing; its elevation and azimuth are the starting guess.</param>
        /// <param name="frame">The frame the swing's angles are given in (forward: toward the field); not the default frame.</param>
        /// <param name="position">The ball's centre at impact, m; finite.</param>
        /// <param name="pitchVelocity">The pitch's velocity at impact, m/s; finite.</param>
        /// <param name="pitchSpin">The pitch's angular velocity, rad/s; finite.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the position.</param>
        /// <param name="maximumAzimuthDegrees">The largest launch azimuth from the target direction the aim solver tries, degrees; in (0, 89].</param>
        /// <returns>The solved swing, or <see cref="AimStatus.Unreachable"/> (elevation within +-45 deg, azimuth within +-90 deg).</returns>
        /// <exception cref="ArgumentException">An argument is not finite, the swing or frame is the default value, the undercut does not reach the ball, or the target is straight above or below the position; the message names it.</exception>
        public SwingSolution<BatSwing> BatPathToReach(
            in BatSwing swing, in LaunchFrame frame, in Vector3d position, in Vector3d pitchVelocity, in Vector3d pitchSpin, in Vector3d target,
            double maximumAzimuthDegrees = 45)
        {
            LaunchFrame aimFrame = Check(frame, position, target, maximumAzimuthDegrees);
            Require.Finite(pitchVelocity, nameof(pitchVelocity));
            Require.Finite(pitchSpin, nameof(pitchSpin));
            RequireBuilt(swing.Speed, nameof(swing), nameof(BatSwing));
            var family = new BatFamily(swing, frame, position, pitchVelocity, pitchSpin, Ball);
            return Solve<BatSwing, BatFamily>(ref family, aimFrame, swing.SwingElevationDegrees, swing.AzimuthDegrees, position, target, maximumAzimuthDegrees);
        }

        /// <summary>
        /// The foot's path elevation and azimuth with which <paramref name="kick"/> (its speed, offset, friction, foot mass
        /// and COR kept: the curl is the player's) sends a ball at rest at <paramref name="position"/> through
        /// <paramref name="target"/> (a point in the goal mouth, or on the pitch: lands there).
        /// </summary>
        /// <param name="kick">The kick; its elevation and azimuth are the starting guess.</param>
        /// <param name="frame">The frame the kick's angles are given in; not the default frame.</param>
        /// <param name="position">The ball's centre, m; finite.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the position.</param>
        /// <param name="maximumAzimuthDegrees">The largest launch azimuth from the target direction the aim solver tries, degrees; in (0, 89].</param>
        /// <returns>The solved kick, or <see cref="AimStatus.Unreachable"/> (elevation within [-45, 60] deg, azimuth within +-90 deg).</returns>
        /// <exception cref="ArgumentException">An argument is not finite, the kick or frame is the default value, the offset is not within the ball's radius, or the target is straight above or below the position; the message names it.</exception>
        public SwingSolution<KickSwing> KickToReach(
            in KickSwing kick, in LaunchFrame frame, in Vector3d position, in Vector3d target, double maximumAzimuthDegrees = 45)
        {
            LaunchFrame aimFrame = Check(frame, position, target, maximumAzimuthDegrees);
            RequireBuilt(kick.Speed, nameof(kick), nameof(KickSwing));
            var family = new KickFamily(kick, frame, position, Ball);
            return Solve<KickSwing, KickFamily>(ref family, aimFrame, kick.ElevationDegrees, kick.AzimuthDegrees, position, target, maximumAzimuthDegrees);
        }

        private LaunchFrame Check(in LaunchFrame frame, in Vector3d position, in Vector3d target, double maximumAzimuthDegrees)
        {
            SwingGeometry.RequireFrame(frame, nameof(frame));
            Require.Finite(position, nameof(position));
            Require.Finite(target, nameof(target));
            Require.InRange(maximumAzimuthDegrees, double.Epsilon, 89, nameof(maximumAzimuthDegrees));
            return AimSolver.TargetFrame(Solver.Model.Up, position, target); // the aim solver's own frame and check
        }

        private static void RequireBuilt(double speed, string name, string type)
        {
            if (speed == 0)
            {
                throw new ArgumentException($"{name} must be built by a {type} constructor; got the default value.", name);
            }
        }
    }
}
