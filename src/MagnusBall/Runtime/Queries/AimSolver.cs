// AimSolver: its public surface (the solves MinimumElevationToClear, ElevationToReach, AnglesToReach, SpeedToReach, each
// checking its arguments and calling its Core). AimSolver.Goals.cs: the target frame, obstacles, via shapes and the shared
// ends of a solve. The solves themselves:
// AimSolver.Elevation.cs (the elevation solves and the bracket-and-refine root finder every one-variable solve uses),
// AimSolver.Speed.cs (the speed solve), AimSolver.Angles.cs (both angles at once: Broyden, then an azimuth search).
using System;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;

namespace MagnusBall.Queries
{
    /// <summary>
    /// Finds launches that do what a player or an AI wants: the lowest elevation that clears a net, the
    /// elevation (and azimuth) or the speed that puts the ball through a target. Each solve starts from the
    /// closed form of a flight in a vacuum, takes secant steps on the real flight until two trials bracket the
    /// answer, and refines it (Illinois regula falsi, falling back to bisection) to 1e-8 rad (5.7e-7 degree) or
    /// 1e-8 m/s; <see cref="AnglesToReach"/> solves both angles at once by Broyden's method. Where that fast path
    /// cannot bracket the answer, the solve falls back to a scan. A target out of reach gives
    /// <see cref="AimStatus.Unreachable"/>, never an exception or a divergence. Allocates nothing per solve.
    /// </summary>
    /// <remarks>
    /// <para><b>Trials.</b> Every trial is a full flight through the one flight core (<see cref="FlightStepper"/>) with
    /// the plane crossing located on the step's dense output. A solver built without an integrator
    /// (<see cref="AimSolver(FlightModel, Plane, double, double, double, double, double, long, ContactShape[])"/>) flies adaptive
    /// Dormand-Prince 5(4) trials (<see cref="FlightStepper.TryStepAdaptive"/>, relative and absolute tolerance
    /// <see cref="TrialTolerance"/> = 1e-8; the early trials of a solve, far from its answer, at 1e-5), events on the
    /// method's own interpolant. Its answers are within 2e-8 rad (1.2e-6 degree) and 1e-7 m/s of the same solve with
    /// RK4 trials at 1/240 s (measured on 24 tennis, free-kick and benchmark solves: 1.05e-8 rad and 4.7e-8 m/s), at 7-9
    /// trials and 224-366 model evaluations per solve on 24 m tennis shots. A solver built with an integrator and
    /// a step flies fixed steps of it, events on each step's cubic Hermite (<see cref="HermiteSegment"/>): its
    /// answers are those of that integrator (use it to aim exactly as a fixed-step game flies), at the cost of
    /// the fixed steps. A trial "arrives" when it crosses the target plane along its normal before it lands on the
    /// ground. A trial launched from exactly on the ground into it lands at once (see
    /// <see cref="HermiteSegment.TryFindCrossing(in Plane, CrossingDirection, bool, out double)"/>); the launch point
    /// should not be below the ground, where a trial lands only after rising through it and coming back down.</para>
    /// <para><b>Which answer.</b> For target solves the frame's forward is the horizontal direction from the launch
    /// point to the target and the target plane passes through the target with that normal. Heights are measured
    /// along up. With <see cref="AimArc.High"/> the highest solution is returned (the lob), found the same way mirrored
    /// (the upper limit, the vacuum's higher elevation, the scan downward). Otherwise the lowest solution is returned (a
    /// drive, not a lob): the lower limit when even it works; else the
    /// root reached from the vacuum's lower angle (or lowest speed), accepted only where the margin grows through it
    /// (below it the shot falls short); else the first one the scan finds upward from the lower limit in steps of the
    /// scan width, so a solution window narrower than the scan width can be missed there.</para>
    /// <para><b>A target below the ground.</b> A trial stops where it lands, so no flight from on or above the ground passes
    /// through a point below it. The target solves then aim at where the ball comes down over it: the answer lands at the
    /// target's horizontal position (its margin jumps there, from landing short to arriving at ground level), is reported
    /// Solved, and <see cref="AimSolution.Miss"/> is the target's depth below the landing. A target given on the court
    /// while the ground plane is at the ball's centre height, one radius up (as the tennis scene's), is such a case:
    /// Miss is the radius.</para>
    /// <para><b>Shapes.</b> A solver built with shapes (<see cref="ContactShape"/>: a net, posts, a backboard, a rim) treats
    /// them as obstacles: the solve's answer is flown once more among them, and an answer that touches one before it reaches
    /// the target is not a solution; the low arc then tries the lob, and where that touches one too the solve returns
    /// <see cref="AimStatus.Blocked"/>. A solve given a viaShapeId aims a bank shot off the shapes of that id: its trials fly
    /// with those shapes alone and arrive only at a crossing of the target's plane after touching them, that plane's normal
    /// being the horizontal direction from the middle of their bounding box to the target (the way the ball comes back); the
    /// answer is then checked among every shape as above. Shapes behind the target (met after the answer arrives) do not
    /// block it. Without shapes the trials and answers are those of a solver without them, bit for bit.</para>
    /// <para>Holds one <see cref="FlightStepper"/>: not thread-safe; create one solver per thread.</para>
    /// </remarks>
    public sealed partial class AimSolver
    {
        /// <summary>Elevation and azimuth are refined to this tolerance, rad (1e-8 rad = 5.7e-7 degree).</summary>
        internal const double AngleTolerance = 1e-8;

        /// <summary>The most trial flights one elevation scan may take (the constructor refuses a finer scan).</summary>
        internal const int MaximumScanTrials = 10_000;

        /// <summary>Speed is refined to this tolerance, m/s.</summary>
        internal const double SpeedTolerance = 1e-8;

        /// <summary>
        /// The work cap of one solve: 1,000,000 model evaluations plus steps over all its trial flights (a step's own work,
        /// its dense output and event scan, costs about one evaluation; a fixed-step RK4 solve of a tennis shot makes a few
        /// thousand, an adaptive one a few hundred; docs/robustness.md). Past it the remaining trials are not flown and the
        /// solve returns <see cref="AimStatus.WorkLimitReached"/>: it bounds a huge maximumFlightTime against a small step,
        /// the finest scans and trials that <see cref="StableIntegrator"/> splits into thousands of substeps.
        /// </summary>
        internal const long MaxEvaluationsPerSolve = 1_000_000;

        /// <summary>The default work budget of an adaptive solver's solve (about 1 ms on a desktop core; an ordinary solve makes 200-700).</summary>
        internal const long DefaultAdaptiveEvaluationsPerSolve = 20_000;

        /// <summary>The smallest work budget a solver takes.</summary>
        internal const long MinimumEvaluationsPerSolve = 1_000;

        /// <summary>The largest work budget a solver takes.</summary>
        internal const long MaximumEvaluationsPerSolveAllowed = 1_000_000_000;

        /// <summary>
        /// The relative and absolute tolerance (m, m/s, rad/s per component) of adaptive trials' Dormand-Prince steps: a 24 m
        /// tennis shot's arrival is then within about 1e-8 m of RK4 at 1/240 s, which moves an elevation root by less than
        /// 1e-9 rad and a speed root by about 5e-8 m/s (the arrival height changes by only 0.2 m per m/s there).
        /// </summary>
        internal const double TrialTolerance = 1e-8;

        /// <summary>The most passes of <see cref="SpeedToReach"/>'s fallback scan (1 % steps up to the maximum speed take 99).</summary>
        private const int MaximumSpeedScanPasses = 101;

        /// <summary>The longest adaptive trial step, s.</summary>
        private const double LongestAdaptiveStep = 0.5;

        /// <summary>
        /// A two-angle solve that converged counts only when its trial passes this close to the target, m: a step of
        /// 1e-8 rad is 1e-6 m at 100 m, so a converged trial is far inside it; a trial that stalls short is not.
        /// </summary>
        private const double ConvergedMiss = 1e-4;

        /// <summary>
        /// A two-angle Broyden solve gives up when its residual (height margin plus sideways miss, m) is not below half of what
        /// it was this many trials earlier: one that converges shrinks it by orders of magnitude in that many trials.
        /// </summary>
        private const int BroydenStallSteps = 5;

        /// <summary>The largest secant step in elevation or azimuth, rad (20 degrees).</summary>
        private const double AngleStride = 0.35;

        /// <summary>The most trials of the reach probe before a scan (golden sections of 125 degrees down to about 1 degree).</summary>
        private const int ProbeTrials = 12;

        /// <summary>The reach probe calls a target out of reach only when its best trial comes this far short, m (the coarse trials' error is far smaller).</summary>
        private const double ProbeSlack = 1e-3;

        /// <summary>The tolerance of the coarse trials (the early trials of an adaptive solve, far from its answer).</summary>
        private const double CoarseTrialTolerance = 1e-5;

        /// <summary>
        /// An adaptive solve's coarse trials find the root to this many times the tolerance (1e-5 rad, 1e-5 m/s: well
        /// outside the coarse trials' own error, about 1e-7 rad), then the full trials move it onto theirs.
        /// </summary>
        private const double CoarseFactor = 1000;

        private static readonly DormandPrince54 TrialMethod = new DormandPrince54(TrialTolerance, TrialTolerance);
        private static readonly DormandPrince54 CoarseMethod = new DormandPrince54(CoarseTrialTolerance, CoarseTrialTolerance);

        private readonly AimTrials _trials;
        private readonly double _gravity;

        /// <summary>Creates a solver whose trials fly fixed steps of <paramref name="integrator"/>.</summary>
        /// <param name="model">The flight model; its gravity must be non-zero (it defines up).</param>
        /// <param name="integrator">The integration method.</param>
        /// <param name="step">The fixed step of each trial flight, s; finite and &gt; 0.</param>
        /// <param name="ground">The ground plane: a trial that lands before reaching its plane falls short. Its normal should be up.</param>
        /// <param name="maximumFlightTime">The longest trial flight, s; finite and &gt; 0.</param>
        /// <param name="minimumElevationDegrees">Lowest elevation tried, degrees; in [-89, 89].</param>
        /// <param name="maximumElevationDegrees">Highest elevation tried, degrees; in [-89, 89], above the lowest.</param>
        /// <param name="elevationScanDegrees">Elevation scan step of the fallback scan, degrees; in (0, 10], and no finer than (maximum - minimum) / <see cref="MaximumScanTrials"/>. A solution window narrower than this can be missed where the scan is used.</param>
        /// <param name="maximumSpeed">Highest speed tried by <see cref="SpeedToReach"/>, m/s; finite and &gt; 0.</param>
        /// <param name="maximumEvaluationsPerSolve">The work budget of one solve: model evaluations plus steps over all its trials; in [1,000, 1e9]. Past it the solve returns <see cref="AimStatus.WorkLimitReached"/>. Fixed steps cost what they cost (an RK4 tennis solve at 1/240 s makes 5,000-15,000), so the default is 1,000,000.</param>
        /// <param name="shapes">The world's shapes (a net, posts, a backboard and rim; copied), obstacles to every solve and the shapes a bank shot can go off (the solves' viaShapeId); null or empty for none. See the remarks.</param>
        /// <exception cref="ArgumentException">An argument is out of range, or an element of shapes is null; the message names it.</exception>
        public AimSolver(
            FlightModel model,
            IIntegrator integrator,
            double step,
            Plane ground,
            double maximumFlightTime = 10,
            double minimumElevationDegrees = -45,
            double maximumElevationDegrees = 80,
            double elevationScanDegrees = 2,
            double maximumSpeed = 100,
            long maximumEvaluationsPerSolve = MaxEvaluationsPerSolve,
            ContactShape[]? shapes = null)
            : this(model, Require.NotNull(integrator, nameof(integrator)), step, ground, maximumFlightTime, minimumElevationDegrees,
                maximumElevationDegrees, elevationScanDegrees, maximumSpeed, maximumEvaluationsPerSolve, adaptive: false, shapes)
        {
        }

        /// <summary>
        /// Creates a solver whose trials fly adaptive Dormand-Prince 5(4) steps (tolerance <see cref="TrialTolerance"/>):
        /// the fast solver for an AI, its answers within 2e-8 rad and 1e-7 m/s of RK4 trials at 1/240 s (see the remarks).
        /// </summary>
        /// <param name="model">The flight model; its gravity must be non-zero (it defines up).</param>
        /// <param name="ground">The ground plane: a trial that lands before reaching its plane falls short. Its normal should be up.</param>
        /// <param name="maximumFlightTime">The longest trial flight, s; finite and &gt; 0.</param>
        /// <param name="minimumElevationDegrees">Lowest elevation tried, degrees; in [-89, 89].</param>
        /// <param name="maximumElevationDegrees">Highest elevation tried, degrees; in [-89, 89], above the lowest.</param>
        /// <param name="elevationScanDegrees">Elevation scan step of the fallback scan, degrees; in (0, 10], and no finer than (maximum - minimum) / <see cref="MaximumScanTrials"/>.</param>
        /// <param name="maximumSpeed">Highest speed tried by <see cref="SpeedToReach"/>, m/s; finite and &gt; 0.</param>
        /// <param name="maximumEvaluationsPerSolve">The work budget of one solve: model evaluations plus steps over all its trials; in [1,000, 1e9]. Past it the solve returns <see cref="AimStatus.WorkLimitReached"/>. The default, 20,000, is about 1 ms of tennis-model work on a desktop core; an ordinary drive makes 200-700, a lob a few thousand (docs/queries.md).</param>
        /// <param name="shapes">The world's shapes (a net, posts, a backboard and rim; copied), obstacles to every solve and the shapes a bank shot can go off (the solves' viaShapeId); null or empty for none. See the remarks.</param>
        /// <exception cref="ArgumentException">An argument is out of range, or an element of shapes is null; the message names it.</exception>
        public AimSolver(
            FlightModel model,
            Plane ground,
            double maximumFlightTime = 10,
            double minimumElevationDegrees = -45,
            double maximumElevationDegrees = 80,
            double elevationScanDegrees = 2,
            double maximumSpeed = 100,
            long maximumEvaluationsPerSolve = DefaultAdaptiveEvaluationsPerSolve,
            ContactShape[]? shapes = null)
            : this(model, TrialMethod, LongestAdaptiveStep, ground, maximumFlightTime, minimumElevationDegrees,
                maximumElevationDegrees, elevationScanDegrees, maximumSpeed, maximumEvaluationsPerSolve, adaptive: true, shapes)
        {
        }

        private AimSolver(
            FlightModel model,
            IIntegrator integrator,
            double step,
            Plane ground,
            double maximumFlightTime,
            double minimumElevationDegrees,
            double maximumElevationDegrees,
            double elevationScanDegrees,
            double maximumSpeed,
            long maximumEvaluationsPerSolve,
            bool adaptive,
            ContactShape[]? shapes)
        {
            Require.NotNull(model, nameof(model));
            if (shapes != null)
            {
                for (int i = 0; i < shapes.Length; i++)
                {
                    if (shapes[i] == null)
                    {
                        throw new ArgumentException($"shapes[{i}] is null; every element must be a shape.", nameof(shapes));
                    }
                }
            }

            if (model.Up.LengthSquared == 0)
            {
                throw new ArgumentException("model must have non-zero gravity: aiming needs an up direction.", nameof(model));
            }

            Step = Require.Step(step, nameof(step));
            if (ground.Normal.LengthSquared == 0)
            {
                throw new ArgumentException("ground must have a non-zero normal (use Plane.Ground(model)).", nameof(ground));
            }

            Ground = ground;
            MaximumFlightTime = Require.Positive(maximumFlightTime, nameof(maximumFlightTime));
            Require.InRange(minimumElevationDegrees, -89, 89, nameof(minimumElevationDegrees));
            Require.InRange(maximumElevationDegrees, -89, 89, nameof(maximumElevationDegrees));
            if (!(maximumElevationDegrees > minimumElevationDegrees))
            {
                throw new ArgumentOutOfRangeException(
                    nameof(maximumElevationDegrees), maximumElevationDegrees,
                    $"maximumElevationDegrees must be above minimumElevationDegrees ({Require.Format(minimumElevationDegrees)}); got {Require.Format(maximumElevationDegrees)}.");
            }

            Require.InRange(elevationScanDegrees, double.Epsilon, 10, nameof(elevationScanDegrees));
            double scanTrials = (maximumElevationDegrees - minimumElevationDegrees) / elevationScanDegrees;
            if (!(scanTrials <= MaximumScanTrials))
            {
                // Bounded work: the elevation scan flies one trial per scan step.
                throw new ArgumentOutOfRangeException(
                    nameof(elevationScanDegrees), elevationScanDegrees,
                    $"elevationScanDegrees must be at least (maximum - minimum elevation) / {MaximumScanTrials} = " +
                    $"{Require.Format((maximumElevationDegrees - minimumElevationDegrees) / MaximumScanTrials)} degrees here (at most {MaximumScanTrials} scan trials per solve), and at most 10; got {Require.Format(elevationScanDegrees)}.");
            }

            MinimumElevationRadians = minimumElevationDegrees * (Math.PI / 180);
            MaximumElevationRadians = maximumElevationDegrees * (Math.PI / 180);
            ElevationScanRadians = elevationScanDegrees * (Math.PI / 180);
            MaximumSpeed = Require.Positive(maximumSpeed, nameof(maximumSpeed));
            if (maximumEvaluationsPerSolve < MinimumEvaluationsPerSolve || maximumEvaluationsPerSolve > MaximumEvaluationsPerSolveAllowed)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(maximumEvaluationsPerSolve), maximumEvaluationsPerSolve,
                    $"maximumEvaluationsPerSolve must be in [{MinimumEvaluationsPerSolve}, {MaximumEvaluationsPerSolveAllowed}] model evaluations plus steps; got {maximumEvaluationsPerSolve}.");
            }

            MaximumEvaluations = maximumEvaluationsPerSolve;
            Model = model;
            Integrator = integrator;
            _gravity = model.Gravity.Length;
            _trials = new AimTrials(model, integrator, step, ground, maximumFlightTime, adaptive, adaptive ? CoarseMethod : null, shapes);
        }

        /// <summary>The flight model.</summary>
        public FlightModel Model { get; }

        /// <summary>The integration method of the trial flights (for adaptive trials, the Dormand-Prince 5(4) method they step with).</summary>
        public IIntegrator Integrator { get; }

        /// <summary>True when the trials fly adaptive Dormand-Prince steps (the solver was built without an integrator).</summary>
        internal bool IsAdaptive => _trials.IsAdaptive;

        /// <summary>The fixed step of the trial flights, s (for adaptive trials, the longest step, 0.5 s).</summary>
        internal double Step { get; }

        /// <summary>The ground plane.</summary>
        internal Plane Ground { get; }

        /// <summary>The longest trial flight, s.</summary>
        internal double MaximumFlightTime { get; }

        /// <summary>Lowest elevation tried, rad.</summary>
        internal double MinimumElevationRadians { get; }

        /// <summary>Highest elevation tried, rad.</summary>
        internal double MaximumElevationRadians { get; }

        /// <summary>Elevation scan step, rad.</summary>
        internal double ElevationScanRadians { get; }

        /// <summary>Highest speed tried, m/s.</summary>
        internal double MaximumSpeed { get; }

        /// <summary>The work budget of one solve (model evaluations plus steps).</summary>
        internal long MaximumEvaluations { get; }

        /// <summary>A caller's lower cap on the next solves' budget (<see cref="SwingAim"/>'s remaining budget); long.MaxValue: none.</summary>
        internal long BudgetCap { get; set; } = long.MaxValue;

        /// <summary>Model evaluations plus steps of the last solve.</summary>
        internal long LastWork => _trials.Work;

        private long SolveBudget => Math.Min(MaximumEvaluations, BudgetCap);

        /// <summary>
        /// (a) The lowest elevation at which a ball launched from <paramref name="position"/> at
        /// <paramref name="speed"/> crosses <paramref name="plane"/> (along its normal, before landing) at least
        /// <paramref name="height"/> above the ground: the minimum angle that clears a net.
        /// </summary>
        /// <param name="position">Launch point, m; finite, on the negative side of the plane (signed distance &lt; 0).</param>
        /// <param name="speed">Launch speed, m/s; finite and &gt; 0.</param>
        /// <param name="azimuthRadians">Azimuth from the plane's normal (its horizontal part) toward the frame's side, rad; finite.</param>
        /// <param name="spin">The spin, by effect relative to the launch direction.</param>
        /// <param name="plane">The plane to clear (a net); its normal must not be vertical.</param>
        /// <param name="height">Height above the ground the ball's centre must pass at, m; finite, and such that the ground's point plus its normal times the height is finite.</param>
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the clearance above the height) or Unreachable. Points near 1e308 m apart give no NaN: a plane beyond what a double holds is Unreachable.</returns>
        /// <exception cref="ArgumentException">An argument is out of range, or the position is not on the plane's negative side; the message names it.</exception>
        public AimSolution MinimumElevationToClear(
            in Vector3d position, double speed, double azimuthRadians, in LaunchSpin spin, in Plane plane, double height) =>
            Finish(MinimumElevationToClearCore(position, speed, azimuthRadians, spin, plane, height));

        /// <summary>
        /// (b) The lowest elevation at which a ball launched from <paramref name="position"/> at
        /// <paramref name="speed"/> toward <paramref name="target"/> (turned by <paramref name="azimuthFromTargetRadians"/>)
        /// passes the target's plane at the target's height; for a target on the ground, lands on it. The lateral
        /// miss (a curving ball) is not corrected: see <see cref="AnglesToReach"/>.
        /// </summary>
        /// <param name="position">Launch point, m; finite.</param>
        /// <param name="speed">Launch speed, m/s; finite and &gt; 0.</param>
        /// <param name="spin">The spin, by effect relative to the launch direction.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the launch point.</param>
        /// <param name="azimuthFromTargetRadians">Azimuth from the direction to the target toward the frame's side, rad; finite.</param>
        /// <param name="arc">The low (flat) or high (lob) solution where both exist.</param>
        /// <param name="obstacle">A wall or net the ball must clear on the way (default: none); its distance short of the target's.</param>
        /// <param name="viaShapeId">A bank shot: the id of the solver's shapes the ball must go off on its way to the target (the backboard); null (the default) for a direct shot.</param>
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the distance from the target), Unreachable (no elevation reaches the target at this speed), Blocked (every one that does hits the obstacle or one of the solver's shapes) or WorkLimitReached.</returns>
        /// <exception cref="ArgumentException">An argument is out of range, or viaShapeId names none of the solver's shapes; the message names it.</exception>
        public AimSolution ElevationToReach(
            in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double azimuthFromTargetRadians = 0,
            AimArc arc = AimArc.Low, AimObstacle obstacle = default, int? viaShapeId = null) =>
            Finish(ElevationToReachCore(position, speed, spin, target, azimuthFromTargetRadians, arc, obstacle, viaShapeId));

        /// <summary>
        /// (b') The elevation and azimuth at which a ball launched from <paramref name="position"/> at
        /// <paramref name="speed"/> passes through <paramref name="target"/>: height by the lowest elevation,
        /// and the sideways miss (a curving ball) by turning the azimuth.
        /// </summary>
        /// <remarks>
        /// Both angles at once by Broyden's method from the vacuum's lower elevation and the azimuth toward the target,
        /// until the step is within <see cref="AngleTolerance"/>; where that does not converge, the elevation solved for
        /// each azimuth and the azimuth refined on the sideways miss (the fallback).
        /// </remarks>
        /// <param name="position">Launch point, m; finite.</param>
        /// <param name="speed">Launch speed, m/s; finite and &gt; 0.</param>
        /// <param name="spin">The spin, by effect relative to the launch direction (sidespin curves toward the frame's side).</param>
        /// <param name="target">The target point, m; finite, not straight above or below the launch point.</param>
        /// <param name="maximumAzimuthDegrees">The largest azimuth turn tried either way, degrees; in (0, 89].</param>
        /// <param name="arc">The low (flat) or high (lob) solution where both exist.</param>
        /// <param name="obstacle">A wall or net the ball must clear on the way (default: none); its distance short of the target's.</param>
        /// <param name="viaShapeId">A bank shot: the id of the solver's shapes the ball must go off on its way to the target (the backboard); null (the default) for a direct shot.</param>
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the distance from the target), Unreachable, Blocked (every launch that reaches the target hits the obstacle or one of the solver's shapes) or WorkLimitReached.</returns>
        /// <exception cref="ArgumentException">An argument is out of range, or viaShapeId names none of the solver's shapes; the message names it.</exception>
        public AimSolution AnglesToReach(
            in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double maximumAzimuthDegrees = 45,
            AimArc arc = AimArc.Low, AimObstacle obstacle = default, int? viaShapeId = null) =>
            Finish(AnglesToReachCore(position, speed, spin, target, maximumAzimuthDegrees, arc, obstacle, viaShapeId));

        /// <summary>
        /// (c) The lowest speed at which a ball launched from <paramref name="position"/> at the given elevation
        /// and azimuth (from the direction to the target) passes the target's plane at the target's height.
        /// </summary>
        /// <param name="position">Launch point, m; finite.</param>
        /// <param name="elevationRadians">Launch elevation, rad; in (-pi/2, pi/2).</param>
        /// <param name="azimuthFromTargetRadians">Azimuth from the direction to the target toward the frame's side, rad; finite.</param>
        /// <param name="spin">The spin, by effect relative to the launch direction.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the launch point.</param>
        /// <param name="obstacle">A wall or net the ball must clear on the way (default: none); its distance short of the target's.</param>
        /// <param name="viaShapeId">A bank shot: the id of the solver's shapes the ball must go off on its way to the target (the backboard); null (the default) for a direct shot.</param>
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the distance from the target), Unreachable, Blocked (the speed that reaches the target hits the obstacle or one of the solver's shapes) or WorkLimitReached.</returns>
        /// <exception cref="ArgumentException">An argument is out of range, or viaShapeId names none of the solver's shapes; the message names it.</exception>
        public AimSolution SpeedToReach(
            in Vector3d position, double elevationRadians, double azimuthFromTargetRadians, in LaunchSpin spin, in Vector3d target,
            AimObstacle obstacle = default, int? viaShapeId = null) =>
            Finish(SpeedToReachCore(position, elevationRadians, azimuthFromTargetRadians, spin, target, obstacle, viaShapeId));
    }
}
