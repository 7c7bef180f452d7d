using System;
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
    /// (<see cref="AimSolver(FlightModel, Plane, double, double, double, double, double)"/>) flies adaptive
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
    /// along up. The lowest solution is returned (a drive, not a lob): the lower limit when even it works; else the
    /// root reached from the vacuum's lower angle (or lowest speed), accepted only where the margin grows through it
    /// (below it the shot falls short); else the first one the scan finds upward from the lower limit in steps of the
    /// scan width, so a solution window narrower than the scan width can be missed there.</para>
    /// <para><b>A target below the ground.</b> A trial stops where it lands, so no flight from on or above the ground passes
    /// through a point below it. The target solves then aim at where the ball comes down over it: the answer lands at the
    /// target's horizontal position (its margin jumps there, from landing short to arriving at ground level), is reported
    /// Solved, and <see cref="AimSolution.Miss"/> is the target's depth below the landing. A target given on the court
    /// while the ground plane is at the ball's centre height, one radius up (as the tennis scene's), is such a case:
    /// Miss is the radius.</para>
    /// <para>Holds one <see cref="FlightStepper"/>: not thread-safe; create one solver per thread.</para>
    /// </remarks>
    public sealed class AimSolver
    {
        /// <summary>Elevation and azimuth are refined to this tolerance, rad (1e-8 rad = 5.7e-7 degree).</summary>
        public const double AngleTolerance = 1e-8;

        /// <summary>The most trial flights one elevation scan may take (the constructor refuses a finer scan).</summary>
        public const int MaximumScanTrials = 10_000;

        /// <summary>Speed is refined to this tolerance, m/s.</summary>
        public const double SpeedTolerance = 1e-8;

        /// <summary>
        /// The work cap of one solve: 1,000,000 model evaluations plus steps over all its trial flights (a step's own work,
        /// its dense output and event scan, costs about one evaluation; a fixed-step RK4 solve of a tennis shot makes a few
        /// thousand, an adaptive one a few hundred; docs/robustness.md). Past it the remaining trials are not flown and the
        /// solve returns <see cref="AimStatus.WorkLimitReached"/>: it bounds a huge maximumFlightTime against a small step,
        /// the finest scans and trials that <see cref="StableIntegrator"/> splits into thousands of substeps.
        /// </summary>
        public const long MaxEvaluationsPerSolve = 1_000_000;

        /// <summary>
        /// The relative and absolute tolerance (m, m/s, rad/s per component) of adaptive trials' Dormand-Prince steps: a 24 m
        /// tennis shot's arrival is then within about 1e-8 m of RK4 at 1/240 s, which moves an elevation root by less than
        /// 1e-9 rad and a speed root by about 5e-8 m/s (the arrival height changes by only 0.2 m per m/s there).
        /// </summary>
        public const double TrialTolerance = 1e-8;

        /// <summary>The most passes of <see cref="SpeedToReach"/>'s fallback scan (1 % steps up to the maximum speed take 99).</summary>
        private const int MaximumSpeedScanPasses = 101;

        /// <summary>The longest adaptive trial step, s.</summary>
        private const double LongestAdaptiveStep = 0.5;

        /// <summary>
        /// A two-angle solve that converged counts only when its trial passes this close to the target, m: a step of
        /// 1e-8 rad is 1e-6 m at 100 m, so a converged trial is far inside it; a trial that stalls short is not.
        /// </summary>
        private const double ConvergedMiss = 1e-4;

        /// <summary>The largest secant step in elevation or azimuth, rad (20 degrees).</summary>
        private const double AngleStride = 0.35;

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
        /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
        public AimSolver(
            FlightModel model,
            IIntegrator integrator,
            double step,
            Plane ground,
            double maximumFlightTime = 10,
            double minimumElevationDegrees = -45,
            double maximumElevationDegrees = 80,
            double elevationScanDegrees = 2,
            double maximumSpeed = 100)
            : this(model, Require.NotNull(integrator, nameof(integrator)), step, ground, maximumFlightTime, minimumElevationDegrees,
                maximumElevationDegrees, elevationScanDegrees, maximumSpeed, adaptive: false)
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
        /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
        public AimSolver(
            FlightModel model,
            Plane ground,
            double maximumFlightTime = 10,
            double minimumElevationDegrees = -45,
            double maximumElevationDegrees = 80,
            double elevationScanDegrees = 2,
            double maximumSpeed = 100)
            : this(model, TrialMethod, LongestAdaptiveStep, ground, maximumFlightTime, minimumElevationDegrees,
                maximumElevationDegrees, elevationScanDegrees, maximumSpeed, adaptive: true)
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
            bool adaptive)
        {
            Require.NotNull(model, nameof(model));
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
            Model = model;
            Integrator = integrator;
            _gravity = model.Gravity.Length;
            _trials = new AimTrials(model, integrator, step, ground, maximumFlightTime, adaptive, adaptive ? CoarseMethod : null);
        }

        /// <summary>The flight model.</summary>
        public FlightModel Model { get; }

        /// <summary>The integration method of the trial flights (for adaptive trials, the Dormand-Prince 5(4) method they step with).</summary>
        public IIntegrator Integrator { get; }

        /// <summary>True when the trials fly adaptive Dormand-Prince steps (the solver was built without an integrator).</summary>
        public bool IsAdaptive => _trials.IsAdaptive;

        /// <summary>The fixed step of the trial flights, s (for adaptive trials, the longest step, 0.5 s).</summary>
        public double Step { get; }

        /// <summary>The ground plane.</summary>
        public Plane Ground { get; }

        /// <summary>The longest trial flight, s.</summary>
        public double MaximumFlightTime { get; }

        /// <summary>Lowest elevation tried, rad.</summary>
        public double MinimumElevationRadians { get; }

        /// <summary>Highest elevation tried, rad.</summary>
        public double MaximumElevationRadians { get; }

        /// <summary>Elevation scan step, rad.</summary>
        public double ElevationScanRadians { get; }

        /// <summary>Highest speed tried, m/s.</summary>
        public double MaximumSpeed { get; }

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

        private AimSolution MinimumElevationToClearCore(
            in Vector3d position, double speed, double azimuthRadians, in LaunchSpin spin, in Plane plane, double height)
        {
            Require.Finite(position, nameof(position));
            Require.Positive(speed, nameof(speed));
            Require.Finite(azimuthRadians, nameof(azimuthRadians));
            Require.Finite(height, nameof(height));
            if (plane.Normal.LengthSquared == 0)
            {
                throw new ArgumentException("plane must have a non-zero normal.", nameof(plane));
            }

            Vector3d up = Model.Up;
            if (Math.Abs(Vector3d.Dot(plane.Normal, up)) > 1 - 1e-9)
            {
                throw new ArgumentException("plane must not be horizontal: clearing is measured by height at the crossing.", nameof(plane));
            }

            double side = plane.SignedDistance(position);
            if (!(side < 0))
            {
                throw new ArgumentException(
                    $"position must be on the negative side of plane (signed distance < 0 m), from where the ball crosses it along its normal; got {Require.Format(side)} m. Flip the plane (Plane.Flipped) to clear it the other way.",
                    nameof(position));
            }

            Vector3d required = Ground.Point + Ground.Normal * height;
            if (!required.IsFinite)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(height), height,
                    $"height must keep the required point, the ground's point plus its normal times the height, within the range of a double; got {Require.Format(height)} m from a ground point {Ground.Point}.");
            }

            var frame = new LaunchFrame(up, plane.Normal);
            var goal = new AimGoal(position, frame, spin, plane, required, missToTarget: false);
            // The vacuum guess: the horizontal path to the plane along the launch's horizontal direction.
            double along = Vector3d.Dot(plane.Normal, frame.Direction(0, azimuthRadians));
            double path = along > 0 ? -side / along : double.NaN;
            _trials.StartSolve();
            return SolveElevation(goal, speed, azimuthRadians, path, double.NaN, out _);
        }

        /// <summary>
        /// (b) The lowest elevation at which a ball launched from <paramref name="position"/> at
        /// <paramref name="speed"/> toward <paramref name="target"/> (turned by <paramref name="azimuthRadians"/>)
        /// passes the target's plane at the target's height; for a target on the ground, lands on it. The lateral
        /// miss (a curving ball) is not corrected: see <see cref="AnglesToReach"/>.
        /// </summary>
        /// <param name="position">Launch point, m; finite.</param>
        /// <param name="speed">Launch speed, m/s; finite and &gt; 0.</param>
        /// <param name="spin">The spin, by effect relative to the launch direction.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the launch point.</param>
        /// <param name="azimuthRadians">Azimuth from the direction to the target toward the frame's side, rad; finite.</param>
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the distance from the target) or Unreachable.</returns>
        /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
        public AimSolution ElevationToReach(in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double azimuthRadians = 0) =>
            Finish(ElevationToReachCore(position, speed, spin, target, azimuthRadians));

        private AimSolution ElevationToReachCore(in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double azimuthRadians)
        {
            CheckTarget(position, target);
            Require.Positive(speed, nameof(speed));
            Require.Finite(azimuthRadians, nameof(azimuthRadians));
            AimGoal goal = TargetGoal(position, target, spin);
            _trials.StartSolve();
            return SolveElevation(goal, speed, azimuthRadians, PathToTarget(goal, azimuthRadians), double.NaN, out _);
        }

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
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the distance from the target) or Unreachable.</returns>
        /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
        public AimSolution AnglesToReach(in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double maximumAzimuthDegrees = 45) =>
            Finish(AnglesToReachCore(position, speed, spin, target, maximumAzimuthDegrees));

        private AimSolution AnglesToReachCore(in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double maximumAzimuthDegrees)
        {
            CheckTarget(position, target);
            Require.Positive(speed, nameof(speed));
            Require.InRange(maximumAzimuthDegrees, double.Epsilon, 89, nameof(maximumAzimuthDegrees));
            double limit = maximumAzimuthDegrees * (Math.PI / 180);
            AimGoal goal = TargetGoal(position, target, spin);
            _trials.StartSolve();
            if (TryBothAngles(goal, speed, limit, out AimSolution solved))
            {
                return solved;
            }

            return AnglesByAzimuthSearch(goal, speed, limit);
        }

        /// <summary>
        /// (c) The lowest speed at which a ball launched from <paramref name="position"/> at the given elevation
        /// and azimuth (from the direction to the target) passes the target's plane at the target's height.
        /// </summary>
        /// <param name="position">Launch point, m; finite.</param>
        /// <param name="elevationRadians">Launch elevation, rad; in (-pi/2, pi/2).</param>
        /// <param name="azimuthRadians">Azimuth from the direction to the target toward the frame's side, rad; finite.</param>
        /// <param name="spin">The spin, by effect relative to the launch direction.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the launch point.</param>
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the distance from the target) or Unreachable.</returns>
        /// <exception cref="ArgumentException">An argument is out of range; the message names it.</exception>
        public AimSolution SpeedToReach(in Vector3d position, double elevationRadians, double azimuthRadians, in LaunchSpin spin, in Vector3d target) =>
            Finish(SpeedToReachCore(position, elevationRadians, azimuthRadians, spin, target));

        private AimSolution SpeedToReachCore(in Vector3d position, double elevationRadians, double azimuthRadians, in LaunchSpin spin, in Vector3d target)
        {
            CheckTarget(position, target);
            Require.InRange(elevationRadians, -0.5 * Math.PI + 1e-9, 0.5 * Math.PI - 1e-9, nameof(elevationRadians));
            Require.Finite(azimuthRadians, nameof(azimuthRadians));
            AimGoal goal = TargetGoal(position, target, spin);
            _trials.StartSolve();
            var margin = new SpeedMargin(_trials, goal, elevationRadians, azimuthRadians);
            double scan = 0.01 * MaximumSpeed;

            // The fast path: from the vacuum's speed, within [1 %, 100 %] of the maximum (below, the scan's crawl rule).
            double guess = VacuumAim.Speed(_gravity, elevationRadians, PathToTarget(goal, azimuthRadians), goal.Rise, out double slope);
            if (SolveFromGuess(ref margin, guess, slope, scan, MaximumSpeed, 0.25 * MaximumSpeed, SpeedTolerance, out _, out AimSolution atRoot))
            {
                return WithFlights(atRoot);
            }

            // The scan: upward in speed from 1 % of the maximum in 1 % steps.
            double lo = scan, flo = margin.Evaluate(lo, out AimSolution atLo);
            if (flo >= 0)
            {
                // Already there at the lowest speed tried: refine between a crawl and it.
                double crawl = 1e-3 * scan;
                double fc = margin.Evaluate(crawl, out AimSolution atCrawl);
                if (fc >= 0)
                {
                    return WithFlights(atCrawl);
                }

                AimRoots.Refine(ref margin, crawl, fc, lo, flo, ref atLo, SpeedTolerance, out _);
                return WithFlights(atLo);
            }

            // Bounded: about 100 passes (1 % steps up to the maximum speed; MaximumSpeedScanPasses caps the count), by count too: a maximum speed below about
            // 1e-322 m/s makes the 1 % step round to 0 (the loop stood still, for ever), and one near double.MaxValue
            // makes the end test's MaximumSpeed (1 + 1e-12) infinite.
            int passes = 0;
            double last = Math.Min(double.MaxValue, MaximumSpeed * (1 + 1e-12)); // no trial at an infinite speed
            for (double v = lo + scan; v <= last && passes < MaximumSpeedScanPasses; v += scan, passes++)
            {
                double fv = margin.Evaluate(v, out AimSolution atV);
                if (fv >= 0)
                {
                    AimRoots.Refine(ref margin, lo, flo, v, fv, ref atV, SpeedTolerance, out _);
                    return WithFlights(atV);
                }

                lo = v;
                flo = fv;
            }

            return UnreachableSpeed(elevationRadians, azimuthRadians);
        }

        private AimSolution UnreachableSpeed(double elevationRadians, double azimuthRadians) =>
            new AimSolution(
                AimStatus.Unreachable, MaximumSpeed, elevationRadians, azimuthRadians, default, default, default, double.PositiveInfinity, _trials.Flights);

        private AimSolution Unreachable(double speed, double azimuth) =>
            new AimSolution(AimStatus.Unreachable, speed, 0, azimuth, default, default, default, double.PositiveInfinity, _trials.Flights);

        // A solution with the solve's flights so far (a solution kept from an earlier trial counts only the flights until then).
        // A solve that reached its work cap says so, whatever its search ended on.
        private AimSolution Finish(in AimSolution s) =>
            _trials.WorkLimitReached
                ? new AimSolution(AimStatus.WorkLimitReached, s.Speed, s.ElevationRadians, s.AzimuthRadians, s.Velocity, s.AngularVelocity, s.Arrival, s.Miss, s.Simulations)
                : s;

        private AimSolution WithFlights(in AimSolution s, AimStatus? status = null) =>
            new AimSolution(status ?? s.Status, s.Speed, s.ElevationRadians, s.AzimuthRadians, s.Velocity, s.AngularVelocity, s.Arrival, s.Miss, _trials.Flights);

        /// <summary>
        /// The fast path of a one-parameter solve: secant steps from the vacuum's guess to the root. With adaptive trials,
        /// first on coarse trials to <see cref="CoarseFactor"/> times the tolerance, then moved onto the full trials
        /// (<see cref="AimRoots.TryPolish"/>, usually two trials); where that does not settle, secant steps on the full trials.
        /// </summary>
        private bool SolveFromGuess<T>(
            ref T margin, double guess, double slope, double min, double max, double stride, double tolerance, out double root, out AimSolution atRoot)
            where T : struct, IAimMargin
        {
            if (_trials.HasCoarse)
            {
                _trials.Coarse = true;
                bool coarse = AimRoots.TrySecant(ref margin, guess, slope, min, max, stride, CoarseFactor * tolerance, out double near, out _, out double nearSlope);
                _trials.Coarse = false;
                if (coarse)
                {
                    if (AimRoots.TryPolish(ref margin, near, nearSlope, min, max, tolerance, out root, out atRoot))
                    {
                        return true;
                    }

                    guess = near;
                    slope = nearSlope;
                }
            }

            return AimRoots.TrySecant(ref margin, guess, slope, min, max, stride, tolerance, out root, out atRoot, out _);
        }

        /// <summary>
        /// The lowest elevation whose trial margin is &gt;= 0, at a fixed speed and azimuth: near a hint (the azimuth
        /// search's last elevation) by a small bracket; else the lower limit when it works, the fast path from the
        /// vacuum's lower elevation over <paramref name="path"/> metres, or the scan upward from the lower limit.
        /// </summary>
        private AimSolution SolveElevation(in AimGoal goal, double speed, double azimuth, double path, double hint, out double elevation)
        {
            var margin = new ElevationMargin(_trials, goal, speed, azimuth);
            double lo, flo, hi, fhi;
            AimSolution atLo, atHi;
            if (double.IsFinite(hint))
            {
                // Near a previous solution (the azimuth search moves it a little): try a small bracket first.
                double width = ElevationScanRadians;
                lo = Math.Max(MinimumElevationRadians, hint - width);
                hi = Math.Min(MaximumElevationRadians, hint + width);
                flo = margin.Evaluate(lo, out _);
                if (flo < 0)
                {
                    fhi = margin.Evaluate(hi, out atHi);
                    if (fhi >= 0)
                    {
                        elevation = AimRoots.Refine(ref margin, lo, flo, hi, fhi, ref atHi, AngleTolerance, out _);
                        return WithFlights(atHi);
                    }
                }
            }

            lo = MinimumElevationRadians;
            flo = margin.Evaluate(lo, out atLo);
            if (flo >= 0)
            {
                // Even the lowest elevation tried does it: report that limit.
                elevation = lo;
                return WithFlights(atLo);
            }

            double guess = VacuumAim.LowElevation(_gravity, speed, path, goal.Rise, out double slope);
            if (SolveFromGuess(ref margin, guess, slope, MinimumElevationRadians, MaximumElevationRadians, AngleStride, AngleTolerance,
                    out elevation, out AimSolution atRoot))
            {
                return WithFlights(atRoot);
            }

            // The scan: bounded by MaximumScanTrials (the constructor checks the scan width).
            for (int i = 1; ; i++)
            {
                hi = Math.Min(MaximumElevationRadians, MinimumElevationRadians + i * ElevationScanRadians);
                fhi = margin.Evaluate(hi, out atHi);
                if (fhi >= 0)
                {
                    elevation = AimRoots.Refine(ref margin, lo, flo, hi, fhi, ref atHi, AngleTolerance, out _);
                    return WithFlights(atHi);
                }

                if (hi >= MaximumElevationRadians)
                {
                    break;
                }

                lo = hi;
                flo = fhi;
            }

            elevation = double.NaN;
            return Unreachable(speed, azimuth);
        }

        /// <summary>
        /// Both angles at once: Broyden's method on r = (height margin at the target plane, sideways miss) over
        /// x = (elevation, azimuth), from the vacuum's lower elevation and azimuth 0 with the vacuum's Jacobian
        /// (diag(d height / d elevation, distance)). Converged when the next step is within <see cref="AngleTolerance"/>
        /// in both angles; accepted only on the drive side (the height grows with elevation), with the lower limit not
        /// working (else the lower limit is the answer, as the fallback finds) and within the limits.
        /// </summary>
        private bool TryBothAngles(in AimGoal goal, double speed, double azimuthLimit, out AimSolution solved)
        {
            solved = default;
            double distance = Vector3d.DotOfDifference(goal.Target, goal.Position, goal.Frame.Forward);
            double e = VacuumAim.LowElevation(_gravity, speed, distance, goal.Rise, out double slope);
            if (double.IsNaN(e) || !(slope > 0))
            {
                return false;
            }

            // The lower limit, at the azimuth toward the target: where it works, the fallback returns it.
            if (!(_trials.Margin(goal, speed, MinimumElevationRadians, 0, out _) < 0))
            {
                return false;
            }

            _trials.Coarse = _trials.HasCoarse;
            bool found = Broyden(goal, speed, azimuthLimit, e, slope, distance, out solved);
            _trials.Coarse = false;
            return found;
        }

        // TryBothAngles's iteration: with adaptive trials first on coarse trials to CoarseFactor times the tolerance, then on
        // the full trials (the first full trial keeps the Jacobian as it is: the change of residual from a coarse to a full
        // trial is the two trials' difference, not the step's effect).
        private bool Broyden(in AimGoal goal, double speed, double azimuthLimit, double e, double slope, double distance, out AimSolution solved)
        {
            solved = default;
            double az = 0;
            double j11 = slope, j12 = 0, j21 = 0, j22 = distance;
            double r1 = 0, r2 = 0, dx1 = 0, dx2 = 0;
            bool update = false;
            for (int k = 0; k < AimRoots.MaximumBroydenSteps; k++)
            {
                if (e < MinimumElevationRadians || e > MaximumElevationRadians || Math.Abs(az) > azimuthLimit)
                {
                    return false;
                }

                double m = _trials.Margin(goal, speed, e, az, out AimSolution s);
                if (!double.IsFinite(m))
                {
                    return false;
                }

                double lateral = Vector3d.DotOfDifference(s.Arrival.Position, goal.Target, goal.Frame.Side);
                if (update)
                {
                    // Broyden's update with the step taken and the change of the residual.
                    double y1 = m - r1 - (j11 * dx1 + j12 * dx2), y2 = lateral - r2 - (j21 * dx1 + j22 * dx2);
                    double dd = dx1 * dx1 + dx2 * dx2;
                    j11 += y1 * dx1 / dd; j12 += y1 * dx2 / dd; j21 += y2 * dx1 / dd; j22 += y2 * dx2 / dd;
                }

                update = true;
                r1 = m;
                r2 = lateral;
                double determinant = j11 * j22 - j12 * j21;
                if (!(Math.Abs(determinant) > 0) || !double.IsFinite(determinant))
                {
                    return false;
                }

                dx1 = -(r1 * j22 - r2 * j12) / determinant;
                dx2 = -(j11 * r2 - j21 * r1) / determinant;
                if (_trials.Coarse && Math.Abs(dx1) <= CoarseFactor * AngleTolerance && Math.Abs(dx2) <= CoarseFactor * AngleTolerance)
                {
                    _trials.Coarse = false;
                    update = false;
                }
                else if (Math.Abs(dx1) <= AngleTolerance && Math.Abs(dx2) <= AngleTolerance)
                {
                    // Converged at this trial (it is within the tolerance of the root), on the drive side, having arrived.
                    if (!(j11 > 0) || !(s.Miss < ConvergedMiss))
                    {
                        return false;
                    }

                    solved = WithFlights(s, AimStatus.Solved);
                    return true;
                }

                double largest = Math.Max(Math.Abs(dx1), Math.Abs(dx2));
                if (largest > AngleStride)
                {
                    dx1 *= AngleStride / largest;
                    dx2 *= AngleStride / largest;
                }

                e += dx1;
                az += dx2;
            }

            return false;
        }

        /// <summary>The fallback of <see cref="AnglesToReach"/>: the azimuth refined on the sideways miss, the elevation solved for each.</summary>
        private AimSolution AnglesByAzimuthSearch(in AimGoal goal, double speed, double limit)
        {
            var lateral = new AzimuthMargin(this, goal, speed);
            double a0 = 0;
            double f0 = lateral.Evaluate(a0, out AimSolution s0);
            if (double.IsNaN(f0))
            {
                return Unreachable(speed, a0);
            }

            if (f0 == 0)
            {
                return WithFlights(s0);
            }

            // The lateral miss grows with azimuth (about distance x azimuth): step toward zero by that estimate,
            // widening until the sign changes.
            double distance = Math.Max(1e-3, Vector3d.DotOfDifference(goal.Target, goal.Position, goal.Frame.Forward));
            double direction = f0 > 0 ? -1 : 1;
            double stride = Math.Min(limit, Math.Max(Math.Abs(f0) / distance * 1.5, 1e-3));
            double a1 = a0, f1 = f0;
            AimSolution s1 = s0;
            // Bounded: the stride is at least 1e-3 rad and the azimuth at most the limit (<= 90 degrees), so at most
            // about 1,600 passes before the limit is reached.
            while (true)
            {
                double next = a1 + direction * stride;
                if (Math.Abs(next) > limit)
                {
                    next = direction * limit;
                }

                double fn = lateral.Evaluate(next, out AimSolution sn);
                if (double.IsNaN(fn))
                {
                    return Unreachable(speed, next);
                }

                if (Math.Sign(fn) != Math.Sign(f0) || fn == 0)
                {
                    a0 = a1;
                    f0 = f1;
                    s0 = s1;
                    a1 = next;
                    f1 = fn;
                    s1 = sn;
                    break;
                }

                if (Math.Abs(next) >= limit)
                {
                    return Unreachable(speed, next);
                }

                a1 = next;
                f1 = fn;
                s1 = sn;
                stride *= 2;
            }

            // Refine between the negative end and the non-negative end.
            bool failed;
            AimSolution atB;
            double root;
            if (f0 < 0)
            {
                atB = s1;
                root = AimRoots.Refine(ref lateral, a0, f0, a1, f1, ref atB, AngleTolerance, out failed);
            }
            else
            {
                atB = s0;
                root = AimRoots.Refine(ref lateral, a1, f1, a0, f0, ref atB, AngleTolerance, out failed);
            }

            return failed ? Unreachable(speed, root) : WithFlights(atB);
        }

        private static void CheckTarget(in Vector3d position, in Vector3d target)
        {
            Require.Finite(position, nameof(position));
            Require.Finite(target, nameof(target));
        }

        private AimGoal TargetGoal(in Vector3d position, in Vector3d target, in LaunchSpin spin)
        {
            LaunchFrame frame = TargetFrame(Model.Up, position, target);
            return new AimGoal(position, frame, spin, new Plane(target, frame.Forward), target, missToTarget: true);
        }

        /// <summary>
        /// The frame of a target solve: <paramref name="up"/>, forward the horizontal direction from
        /// <paramref name="position"/> to <paramref name="target"/> (formed from quarters where the difference overflows).
        /// </summary>
        /// <exception cref="ArgumentException">The target is within 1e-6 m of straight above or below the position (names target).</exception>
        internal static LaunchFrame TargetFrame(in Vector3d up, in Vector3d position, in Vector3d target)
        {
            Vector3d toTarget = target - position;
            Vector3d horizontal = toTarget - up * Vector3d.Dot(toTarget, up);
            double length = horizontal.Length;
            if (!double.IsFinite(length))
            {
                // The target near 1e308 away: the difference (or its part along up) overflowed. Its quarter does not
                // (quartering is exact but for subnormals), and the frame needs only the direction.
                Vector3d quarter = 0.25 * target - 0.25 * position;
                horizontal = quarter - up * Vector3d.Dot(quarter, up);
                length = 4 * horizontal.Length;
            }

            if (!(length > 1e-6))
            {
                throw new ArgumentException(
                    $"target must not be straight above or below the launch point (horizontal distance {Require.Format(length)} m).",
                    nameof(target));
            }

            try
            {
                return new LaunchFrame(up, horizontal);
            }
            catch (ArgumentException)
            {
                // The horizontal part is over 1e-6 m but within LaunchFrame's 1e-9 of its own length of up: rounding left
                // over from a target far along up (a horizontal of 4e292 m beside 1.8e308 m along a tilted up). The caller
                // gave a target, not a forward: name it.
                throw new ArgumentException(
                    $"target must not be straight above or below the launch point (horizontal distance {Require.Format(length)} m is rounding beside its distance along up).",
                    nameof(target));
            }
        }

        // The horizontal path from the launch point to the target plane along the azimuth (NaN when it never gets there).
        private static double PathToTarget(in AimGoal goal, double azimuth)
        {
            double along = Vector3d.Dot(goal.Frame.Forward, goal.Frame.Direction(0, azimuth));
            return along > 0 ? Vector3d.DotOfDifference(goal.Target, goal.Position, goal.Frame.Forward) / along : double.NaN;
        }

        private struct ElevationMargin : IAimMargin
        {
            private readonly AimTrials _trials;
            private readonly AimGoal _goal;
            private readonly double _speed;
            private readonly double _azimuth;

            public ElevationMargin(AimTrials trials, in AimGoal goal, double speed, double azimuth)
            {
                _trials = trials;
                _goal = goal;
                _speed = speed;
                _azimuth = azimuth;
            }

            public double Evaluate(double elevation, out AimSolution solution) => _trials.Margin(_goal, _speed, elevation, _azimuth, out solution);
        }

        private struct SpeedMargin : IAimMargin
        {
            private readonly AimTrials _trials;
            private readonly AimGoal _goal;
            private readonly double _elevation;
            private readonly double _azimuth;

            public SpeedMargin(AimTrials trials, in AimGoal goal, double elevation, double azimuth)
            {
                _trials = trials;
                _goal = goal;
                _elevation = elevation;
                _azimuth = azimuth;
            }

            public double Evaluate(double speed, out AimSolution solution) => _trials.Margin(_goal, speed, _elevation, _azimuth, out solution);
        }

        private struct AzimuthMargin : IAimMargin
        {
            private readonly AimSolver _solver;
            private readonly AimGoal _goal;
            private readonly double _speed;
            private double _hint;

            public AzimuthMargin(AimSolver solver, in AimGoal goal, double speed)
            {
                _solver = solver;
                _goal = goal;
                _speed = speed;
                _hint = double.NaN;
            }

            /// <summary>The sideways miss (along the frame's side) after solving the elevation; NaN when no elevation reaches the height.</summary>
            public double Evaluate(double azimuth, out AimSolution solution)
            {
                solution = _solver.SolveElevation(_goal, _speed, azimuth, PathToTarget(_goal, azimuth), _hint, out double elevation);
                if (!solution.IsSolved)
                {
                    return double.NaN;
                }

                _hint = elevation;
                return Vector3d.DotOfDifference(solution.Arrival.Position, _goal.Target, _goal.Frame.Side);
            }
        }
    }
}
