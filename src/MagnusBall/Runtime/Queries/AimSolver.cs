using System;
using MagnusBall.Flight;
using MagnusBall.Integration;

namespace MagnusBall.Queries
{
    /// <summary>Whether an aim solver found a launch.</summary>
    public enum AimStatus
    {
        /// <summary>A launch was found to the solver's tolerance.</summary>
        Solved = 0,

        /// <summary>No launch within the solver's limits does it; nothing was thrown and nothing diverged.</summary>
        Unreachable = 1,

        /// <summary>
        /// The solve stopped at its work cap (<see cref="AimSolver.MaxEvaluationsPerSolve"/> model evaluations plus steps) before it
        /// could decide; the launch fields hold where it was. Fly shorter trials (a smaller maximumFlightTime), a larger
        /// step or a coarser scan.
        /// </summary>
        WorkLimitReached = 2,
    }

    /// <summary>
    /// The result of an aim solve: the status, the launch (speed, elevation, azimuth, and the world-frame
    /// velocity and spin they resolve to), where the solved shot arrives, and what the solve cost.
    /// </summary>
    public readonly struct AimSolution
    {
        /// <summary>Creates a result.</summary>
        /// <param name="status">Solved or unreachable.</param>
        /// <param name="speed">Launch speed, m/s.</param>
        /// <param name="elevationRadians">Launch elevation, rad.</param>
        /// <param name="azimuthRadians">Launch azimuth from the frame's forward toward its side, rad.</param>
        /// <param name="velocity">Launch velocity, m/s (world frame).</param>
        /// <param name="angularVelocity">Launch angular velocity, rad/s (world frame).</param>
        /// <param name="arrival">The solved shot's state where it crosses the target or obstacle plane.</param>
        /// <param name="miss">See <see cref="Miss"/>.</param>
        /// <param name="simulations">Flights simulated.</param>
        public AimSolution(
            AimStatus status, double speed, double elevationRadians, double azimuthRadians, in Vector3d velocity, in Vector3d angularVelocity,
            in FlightState arrival, double miss, int simulations)
        {
            Status = status;
            Speed = speed;
            ElevationRadians = elevationRadians;
            AzimuthRadians = azimuthRadians;
            Velocity = velocity;
            AngularVelocity = angularVelocity;
            Arrival = arrival;
            Miss = miss;
            Simulations = simulations;
        }

        /// <summary>Solved or unreachable. When unreachable, the other fields describe the best attempt or are zero.</summary>
        public readonly AimStatus Status;

        /// <summary>Launch speed, m/s.</summary>
        public readonly double Speed;

        /// <summary>Launch elevation above the horizontal, rad.</summary>
        public readonly double ElevationRadians;

        /// <summary>Launch azimuth about up, from the frame's forward toward its side, rad (see <see cref="LaunchFrame"/>).</summary>
        public readonly double AzimuthRadians;

        /// <summary>The launch velocity in the world frame, m/s: Speed times the launch direction.</summary>
        public readonly Vector3d Velocity;

        /// <summary>The launch angular velocity in the world frame, rad/s (the <see cref="LaunchSpin"/> resolved for this launch).</summary>
        public readonly Vector3d AngularVelocity;

        /// <summary>The solved shot's interpolated state where it crosses the target plane (or the obstacle plane).</summary>
        public readonly FlightState Arrival;

        /// <summary>
        /// For target solves, the distance from <see cref="Arrival"/> to the target, m. For
        /// <see cref="AimSolver.MinimumElevationToClear"/>, how far above the required height the solved shot
        /// crosses the plane, m (0 up to the tolerance).
        /// </summary>
        public readonly double Miss;

        /// <summary>How many flights the solve simulated (its cost: each is a full prediction).</summary>
        public readonly int Simulations;

        /// <summary>True when <see cref="Status"/> is <see cref="AimStatus.Solved"/>.</summary>
        public bool IsSolved => Status == AimStatus.Solved;

        /// <summary>Launch elevation, degrees.</summary>
        public double ElevationDegrees => ElevationRadians * (180 / Math.PI);

        /// <summary>Launch azimuth, degrees.</summary>
        public double AzimuthDegrees => AzimuthRadians * (180 / Math.PI);

        /// <summary>The launch state at <paramref name="position"/>: the solved velocity and spin.</summary>
        /// <param name="position">The launch point, m.</param>
        /// <param name="time">The launch time, s.</param>
        public FlightState LaunchState(in Vector3d position, double time = 0) => new FlightState(position, Velocity, AngularVelocity, time);

        /// <inheritdoc />
        public override string ToString() =>
            $"{Status}: speed {Speed:R} m/s, elevation {ElevationDegrees:R} deg, azimuth {AzimuthDegrees:R} deg, miss {Miss:R} m, {Simulations} flights";
    }

    /// <summary>
    /// Finds launches that do what a player or an AI wants: the lowest elevation that clears a net, the
    /// elevation (and azimuth) or the speed that puts the ball through a target. Each solve brackets the
    /// answer by scanning, then refines it (Illinois regula falsi, falling back to bisection) to better than
    /// 1e-6 degree or 1e-8 m/s; a target out of reach gives <see cref="AimStatus.Unreachable"/>, never an
    /// exception or a divergence. Allocates nothing per solve.
    /// </summary>
    /// <remarks>
    /// <para>Every trial is a full flight with the solver's model, integrator and fixed step, with the plane
    /// crossing located on the step's cubic Hermite (<see cref="HermiteSegment"/>). A trial "arrives" when it
    /// crosses the target plane along its normal before it lands on the ground. A trial launched from exactly
    /// on the ground into it lands at once (see <see cref="HermiteSegment.TryFindCrossing(in Plane, CrossingDirection, bool, out double)"/>);
    /// the launch point should not be below the ground, where a trial lands only after rising through it and
    /// coming back down.</para>
    /// <para>For target solves the frame's forward is the horizontal direction from the launch point to the
    /// target and the target plane passes through the target with that normal. Heights are measured along
    /// up. The elevation scan runs upward from the lower limit in steps of the scan width, so the lowest
    /// solution is returned (a drive, not a lob); a solution window narrower than the scan width can be
    /// missed, and when even the lower limit works, the lower limit is returned.</para>
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
        /// its dense output and event scan, costs about one evaluation; a default solve of a tennis shot makes about 10^5;
        /// up to 4 s on a loaded core, docs/robustness.md). Past it the remaining trials are not flown and the solve returns
        /// <see cref="AimStatus.WorkLimitReached"/>: it bounds a huge maximumFlightTime against a small step, the finest
        /// scans and trials that <see cref="StableIntegrator"/> splits into thousands of substeps.
        /// </summary>
        public const long MaxEvaluationsPerSolve = 1_000_000;

        private readonly FlightStepper _stepper;
        private readonly Plane[] _trialPlane = new Plane[1]; // the plane of the current trial, watched by _stepper's event set
        private int _simulations;
        private long _evaluations;       // model evaluations plus steps of the solve so far (the finished trials)
        private bool _workLimitReached;  // the solve reached MaxEvaluationsPerSolve

        /// <summary>Creates a solver.</summary>
        /// <param name="model">The flight model; its gravity must be non-zero (it defines up).</param>
        /// <param name="integrator">The integration method.</param>
        /// <param name="step">The fixed step of each trial flight, s; finite and &gt; 0.</param>
        /// <param name="ground">The ground plane: a trial that lands before reaching its plane falls short. Its normal should be up.</param>
        /// <param name="maximumFlightTime">The longest trial flight, s; finite and &gt; 0.</param>
        /// <param name="minimumElevationDegrees">Lowest elevation tried, degrees; in [-89, 89].</param>
        /// <param name="maximumElevationDegrees">Highest elevation tried, degrees; in [-89, 89], above the lowest.</param>
        /// <param name="elevationScanDegrees">Elevation scan step, degrees; in (0, 10], and no finer than (maximum - minimum) / <see cref="MaximumScanTrials"/>. A solution window narrower than this can be missed.</param>
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
        {
            Require.NotNull(model, nameof(model));
            Require.NotNull(integrator, nameof(integrator));
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
            // The trials fly through the one flight core; their event set watches the ground and one plane, which each
            // trial sets (the set shares _trialPlane instead of copying it: no allocation per trial).
            _stepper = new FlightStepper(model, integrator, FlightEventSet.Sharing(ground, _trialPlane));
        }

        /// <summary>The flight model.</summary>
        public FlightModel Model => _stepper.Model;

        /// <summary>The integration method of the trial flights.</summary>
        public IIntegrator Integrator => _stepper.Integrator;

        /// <summary>The fixed step of the trial flights, s.</summary>
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
        /// <param name="height">Height above the ground the ball's centre must pass at, m; finite.</param>
        /// <returns>The solution (<see cref="AimSolution.Miss"/> is the clearance above the height) or Unreachable.</returns>
        /// <exception cref="ArgumentException">An argument is out of range, or the position is not on the plane's negative side; the message names it.</exception>
        public AimSolution MinimumElevationToClear(in Vector3d position, double speed, double azimuthRadians, in LaunchSpin spin, in Plane plane, double height) =>
            Finish(MinimumElevationToClearCore(position, speed, azimuthRadians, spin, plane, height));

        private AimSolution MinimumElevationToClearCore(in Vector3d position, double speed, double azimuthRadians, in LaunchSpin spin, in Plane plane, double height)
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

            var frame = new LaunchFrame(up, plane.Normal);
            BeginSolve();
            var margin = new ElevationMargin(this, position, frame, speed, azimuthRadians, spin, plane, Ground.Point + Ground.Normal * height, false);
            return SolveElevation(ref margin, position, frame, speed, azimuthRadians, spin, double.NaN, out _);
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
            TargetFrame(position, target, out LaunchFrame frame, out Plane plane);
            BeginSolve();
            var margin = new ElevationMargin(this, position, frame, speed, azimuthRadians, spin, plane, target, true);
            return SolveElevation(ref margin, position, frame, speed, azimuthRadians, spin, double.NaN, out _);
        }

        /// <summary>
        /// (b') The elevation and azimuth at which a ball launched from <paramref name="position"/> at
        /// <paramref name="speed"/> passes through <paramref name="target"/>: height by the lowest elevation,
        /// and the sideways miss (a curving ball) by turning the azimuth.
        /// </summary>
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
            TargetFrame(position, target, out LaunchFrame frame, out Plane plane);
            BeginSolve();

            var lateral = new AzimuthMargin(this, position, frame, speed, spin, plane, target);
            double a0 = 0;
            double f0 = lateral.Evaluate(a0);
            if (double.IsNaN(f0))
            {
                return Unreachable(speed, a0);
            }

            if (f0 == 0)
            {
                return lateral.Last;
            }

            // The lateral miss grows with azimuth (about distance x azimuth): step toward zero by that estimate,
            // widening until the sign changes.
            double distance = Math.Max(1e-3, Vector3d.Dot(target - position, frame.Forward));
            double direction = f0 > 0 ? -1 : 1;
            double stride = Math.Min(limit, Math.Max(Math.Abs(f0) / distance * 1.5, 1e-3));
            double a1 = a0, f1 = f0;
            // Bounded: the stride is at least 1e-3 rad and the azimuth at most the limit (<= 90 degrees), so at most
            // about 1,600 passes before the limit is reached.
            while (true)
            {
                double next = a1 + direction * stride;
                if (Math.Abs(next) > limit)
                {
                    next = direction * limit;
                }

                double fn = lateral.Evaluate(next);
                if (double.IsNaN(fn))
                {
                    return Unreachable(speed, next);
                }

                if (Math.Sign(fn) != Math.Sign(f0) || fn == 0)
                {
                    a0 = a1;
                    f0 = f1;
                    a1 = next;
                    f1 = fn;
                    break;
                }

                if (Math.Abs(next) >= limit)
                {
                    return Unreachable(speed, next);
                }

                a1 = next;
                f1 = fn;
                stride *= 2;
            }

            // Refine between the negative end and the non-negative end.
            double root = f0 < 0
                ? Refine(ref lateral, a0, f0, a1, f1, AngleTolerance, out bool failed)
                : Refine(ref lateral, a1, f1, a0, f0, AngleTolerance, out failed);
            if (failed)
            {
                return Unreachable(speed, root);
            }

            double final = lateral.Evaluate(root);
            return double.IsNaN(final) ? Unreachable(speed, root) : lateral.Last;
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
            TargetFrame(position, target, out LaunchFrame frame, out Plane plane);
            BeginSolve();
            var margin = new SpeedMargin(this, position, frame, elevationRadians, azimuthRadians, spin, plane, target);

            // Scan upward in speed: 1% of the maximum, then 1% steps.
            double scan = 0.01 * MaximumSpeed;
            double lo = scan, flo = margin.Evaluate(lo);
            if (flo >= 0)
            {
                // Already there at the lowest speed tried: refine between a crawl and it.
                double crawl = 1e-3 * scan;
                double fc = margin.Evaluate(crawl);
                if (fc >= 0)
                {
                    return margin.Last;
                }

                double v0 = Refine(ref margin, crawl, fc, lo, flo, SpeedTolerance, out _);
                margin.Evaluate(v0);
                return margin.Last;
            }

            for (double v = lo + scan; v <= MaximumSpeed * (1 + 1e-12); v += scan)
            {
                double fv = margin.Evaluate(v);
                if (fv >= 0)
                {
                    double root = Refine(ref margin, lo, flo, v, fv, SpeedTolerance, out _);
                    margin.Evaluate(root);
                    return margin.Last;
                }

                lo = v;
                flo = fv;
            }

            return new AimSolution(
                AimStatus.Unreachable, MaximumSpeed, elevationRadians, azimuthRadians, default, default, default, double.PositiveInfinity, _simulations);
        }

        private void BeginSolve()
        {
            _simulations = 0;
            _evaluations = 0;
            _workLimitReached = false;
        }

        // A solve that reached its work cap says so, whatever its search ended on.
        private AimSolution Finish(in AimSolution s) =>
            _workLimitReached
                ? new AimSolution(AimStatus.WorkLimitReached, s.Speed, s.ElevationRadians, s.AzimuthRadians, s.Velocity, s.AngularVelocity, s.Arrival, s.Miss, s.Simulations)
                : s;

        private AimSolution Unreachable(double speed, double azimuth) =>
            new AimSolution(AimStatus.Unreachable, speed, 0, azimuth, default, default, default, double.PositiveInfinity, _simulations);

        private AimSolution SolveElevation(
            ref ElevationMargin margin, in Vector3d position, in LaunchFrame frame, double speed, double azimuth, in LaunchSpin spin,
            double hint, out double elevation)
        {
            elevation = double.NaN;
            double lo = 0, flo = 0, hi = 0, fhi = 0;
            bool bracketed = false;

            if (double.IsFinite(hint))
            {
                // Near a previous solution (the azimuth search moves it a little): try a small bracket first.
                double width = ElevationScanRadians;
                lo = Math.Max(MinimumElevationRadians, hint - width);
                hi = Math.Min(MaximumElevationRadians, hint + width);
                flo = margin.Evaluate(lo);
                if (flo < 0)
                {
                    fhi = margin.Evaluate(hi);
                    bracketed = fhi >= 0;
                }
            }

            if (!bracketed)
            {
                lo = MinimumElevationRadians;
                flo = margin.Evaluate(lo);
                if (flo >= 0)
                {
                    // Even the lowest elevation tried does it: report that limit.
                    elevation = lo;
                    return margin.Last;
                }

                for (int i = 1; ; i++)
                {
                    hi = Math.Min(MaximumElevationRadians, MinimumElevationRadians + i * ElevationScanRadians);
                    fhi = margin.Evaluate(hi);
                    if (fhi >= 0)
                    {
                        bracketed = true;
                        break;
                    }

                    if (hi >= MaximumElevationRadians)
                    {
                        break;
                    }

                    lo = hi;
                    flo = fhi;
                }
            }

            if (!bracketed)
            {
                return new AimSolution(AimStatus.Unreachable, speed, 0, azimuth, default, default, default, double.PositiveInfinity, _simulations);
            }

            double root = Refine(ref margin, lo, flo, hi, fhi, AngleTolerance, out _);
            margin.Evaluate(root);
            elevation = root;
            return margin.Last;
        }

        /// <summary>
        /// Refines a bracket between <paramref name="a"/> (f &lt; 0) and <paramref name="b"/> (f &gt;= 0), in
        /// either order, to the tolerance by the Illinois method (regula falsi that halves the stale end's value),
        /// bisecting when a value is not finite, every fourth step, or when the secant hugs an end. Returns the
        /// end where f &gt;= 0; <paramref name="failed"/> when f returned NaN.
        /// </summary>
        private static double Refine<T>(ref T f, double a, double fa, double b, double fb, double tolerance, out bool failed)
            where T : struct, IMargin
        {
            failed = false;
            int side = 0;
            double checkpoint = Math.Abs(b - a);
            bool bisect = false;
            for (int i = 0; i < 200 && Math.Abs(b - a) > tolerance; i++)
            {
                double width = b - a;
                if (i % 3 == 2)
                {
                    // Safeguard: if three steps did not halve the bracket, bisect once.
                    bisect = Math.Abs(width) > 0.5 * checkpoint;
                    checkpoint = Math.Abs(width);
                }

                double t = 0.5;
                if (!bisect && double.IsFinite(fa) && double.IsFinite(fb) && fb > fa)
                {
                    // Regula falsi, kept at least a quarter of the tolerance inside the bracket.
                    double margin = Math.Min(0.25, 0.25 * tolerance / Math.Abs(width));
                    t = Math.Max(margin, Math.Min(1 - margin, -fa / (fb - fa)));
                }

                bisect = false;
                double x = a + width * t;
                double fx = f.Evaluate(x);
                if (double.IsNaN(fx))
                {
                    failed = true;
                    return x;
                }

                if (fx >= 0)
                {
                    b = x;
                    fb = fx;
                    if (side == 1 && double.IsFinite(fa))
                    {
                        fa *= 0.5;
                    }

                    side = 1;
                }
                else
                {
                    a = x;
                    fa = fx;
                    if (side == -1)
                    {
                        fb *= 0.5;
                    }

                    side = -1;
                }
            }

            return b;
        }

        private static void CheckTarget(in Vector3d position, in Vector3d target)
        {
            Require.Finite(position, nameof(position));
            Require.Finite(target, nameof(target));
        }

        private void TargetFrame(in Vector3d position, in Vector3d target, out LaunchFrame frame, out Plane plane)
        {
            Vector3d up = Model.Up;
            Vector3d toTarget = target - position;
            Vector3d horizontal = toTarget - up * Vector3d.Dot(toTarget, up);
            if (!(horizontal.Length > 1e-6))
            {
                throw new ArgumentException(
                    $"target must not be straight above or below the launch point (horizontal distance {Require.Format(horizontal.Length)} m).",
                    nameof(target));
            }

            frame = new LaunchFrame(up, horizontal);
            plane = new Plane(target, frame.Forward);
        }

        /// <summary>
        /// Flies one trial to <paramref name="plane"/>: true with the crossing state when the ball crosses it
        /// along its normal before landing; false with the landing (or last) state otherwise.
        /// </summary>
        private bool Shoot(in FlightState launch, in Plane plane, out FlightState arrival, out bool landed)
        {
            if (_workLimitReached)
            {
                // Past the work cap: no more trials are flown (each fails), so the solve ends quickly.
                arrival = launch;
                landed = false;
                return false;
            }

            bool arrived = Fly(launch, plane, out arrival, out landed);
            _evaluations += _stepper.DerivativeEvaluations + _stepper.StepCount;
            return arrived;
        }

        private bool Fly(in FlightState launch, in Plane plane, out FlightState arrival, out bool landed)
        {
            _simulations++;
            FlightStepper stepper = _stepper;
            _trialPlane[0] = plane;
            stepper.Reset(launch);
            double endTime = launch.Time + MaximumFlightTime;
            // Bounded: each pass advances the clock by a step, at most MaximumFlightTime / Step + 1 passes, and none past
            // the solve's work cap; the last step is trimmed to the time limit (the one end-time rule).
            while (true)
            {
                if (_evaluations + stepper.DerivativeEvaluations + stepper.StepCount >= MaxEvaluationsPerSolve)
                {
                    _workLimitReached = true; // this trial fails; the solve returns WorkLimitReached
                    break;
                }

                double h = FlightStepper.StepToward(stepper.State.Time, endTime, Step, out bool last);
                StepOutcome outcome = stepper.TryStep(h, FlightEventKinds.Landing | FlightEventKinds.PlaneCrossing);
                if (outcome == StepOutcome.Diverged || outcome == StepOutcome.TimeCannotAdvance)
                {
                    break; // this trial fails (margin -infinity), the solve goes on
                }

                if (stepper.IsStopped)
                {
                    // A crossing at the same instant as the landing still arrives.
                    foreach (FlightEvent e in SpanView.Of(stepper.Events)) // not ReadOnlySpan's enumerator: Mono 6.8 lacks it
                    {
                        if (e.Kind == FlightEventKinds.PlaneCrossing)
                        {
                            arrival = e.State;
                            landed = false;
                            return true;
                        }
                    }

                    arrival = stepper.StopEvent.State;
                    landed = true;
                    return false;
                }

                if (last)
                {
                    break;
                }
            }

            arrival = stepper.State;
            landed = false;
            return false;
        }

        /// <summary>
        /// The signed margin of one trial: &gt;= 0 when it arrives at or above the wanted height, &lt; 0 when
        /// below or short (the landing's signed distance to the plane, so it is continuous for ground targets),
        /// negative infinity when it neither lands nor arrives in time.
        /// </summary>
        private double ArrivalMargin(in FlightState launch, in Plane plane, in Vector3d heightPoint, out FlightState arrival)
        {
            if (Shoot(launch, plane, out arrival, out bool landed))
            {
                return Vector3d.Dot(arrival.Position - heightPoint, Model.Up);
            }

            return landed ? Math.Min(plane.SignedDistance(arrival.Position), -double.Epsilon) : double.NegativeInfinity;
        }

        /// <summary>
        /// One trial launch at the given speed, elevation and azimuth: its margin (see <see cref="ArrivalMargin"/>)
        /// and the solution it stands for. <paramref name="missToTarget"/>: Miss is the distance from the arrival
        /// to the target; otherwise the margin (the clearance above the wanted height).
        /// </summary>
        private double Trial(
            in Vector3d position, in LaunchFrame frame, double speed, double elevation, double azimuth, in LaunchSpin launchSpin, in Plane plane,
            in Vector3d target, bool missToTarget, out AimSolution solution)
        {
            Vector3d direction = frame.Direction(elevation, azimuth);
            Vector3d velocity = direction * speed;
            Vector3d spin = launchSpin.AngularVelocity(direction, frame);
            double margin = ArrivalMargin(new FlightState(position, velocity, spin), plane, target, out FlightState arrival);
            double miss = missToTarget ? Vector3d.Distance(arrival.Position, target) : margin;
            solution = new AimSolution(
                margin >= 0 ? AimStatus.Solved : AimStatus.Unreachable, speed, elevation, azimuth, velocity, spin, arrival, miss, _simulations);
            return margin;
        }

        private interface IMargin
        {
            double Evaluate(double x);
        }

        private struct ElevationMargin : IMargin
        {
            private readonly AimSolver _solver;
            private readonly Vector3d _position;
            private readonly LaunchFrame _frame;
            private readonly double _speed;
            private readonly double _azimuth;
            private readonly LaunchSpin _spin;
            private readonly Plane _plane;
            private readonly Vector3d _target;
            private readonly bool _missToTarget;

            public ElevationMargin(
                AimSolver solver, in Vector3d position, in LaunchFrame frame, double speed, double azimuth, in LaunchSpin spin, in Plane plane,
                in Vector3d target, bool missToTarget)
            {
                _solver = solver;
                _position = position;
                _frame = frame;
                _speed = speed;
                _azimuth = azimuth;
                _spin = spin;
                _plane = plane;
                _target = target;
                _missToTarget = missToTarget;
                Last = default;
            }

            public AimSolution Last { get; private set; }

            public double Evaluate(double elevation)
            {
                double margin = _solver.Trial(_position, _frame, _speed, elevation, _azimuth, _spin, _plane, _target, _missToTarget, out AimSolution solution);
                Last = solution;
                return margin;
            }
        }

        private struct AzimuthMargin : IMargin
        {
            private readonly AimSolver _solver;
            private readonly Vector3d _position;
            private readonly LaunchFrame _frame;
            private readonly double _speed;
            private readonly LaunchSpin _spin;
            private readonly Plane _plane;
            private readonly Vector3d _target;
            private double _hint;

            public AzimuthMargin(AimSolver solver, in Vector3d position, in LaunchFrame frame, double speed, in LaunchSpin spin, in Plane plane, in Vector3d target)
            {
                _solver = solver;
                _position = position;
                _frame = frame;
                _speed = speed;
                _spin = spin;
                _plane = plane;
                _target = target;
                _hint = double.NaN;
                Last = default;
            }

            public AimSolution Last { get; private set; }

            /// <summary>The sideways miss (along the frame's side) after solving the elevation; NaN when no elevation reaches the height.</summary>
            public double Evaluate(double azimuth)
            {
                var margin = new ElevationMargin(_solver, _position, _frame, _speed, azimuth, _spin, _plane, _target, true);
                AimSolution solution = _solver.SolveElevation(ref margin, _position, _frame, _speed, azimuth, _spin, _hint, out double elevation);
                Last = solution;
                if (!solution.IsSolved)
                {
                    return double.NaN;
                }

                _hint = elevation;
                return Vector3d.Dot(solution.Arrival.Position - _target, _frame.Side);
            }
        }

        private struct SpeedMargin : IMargin
        {
            private readonly AimSolver _solver;
            private readonly Vector3d _position;
            private readonly LaunchFrame _frame;
            private readonly double _elevation;
            private readonly double _azimuth;
            private readonly LaunchSpin _spin;
            private readonly Plane _plane;
            private readonly Vector3d _target;

            public SpeedMargin(
                AimSolver solver, in Vector3d position, in LaunchFrame frame, double elevation, double azimuth, in LaunchSpin spin, in Plane plane,
                in Vector3d target)
            {
                _solver = solver;
                _position = position;
                _frame = frame;
                _elevation = elevation;
                _azimuth = azimuth;
                _spin = spin;
                _plane = plane;
                _target = target;
                Last = default;
            }

            public AimSolution Last { get; private set; }

            public double Evaluate(double speed)
            {
                double margin = _solver.Trial(_position, _frame, speed, _elevation, _azimuth, _spin, _plane, _target, true, out AimSolution solution);
                Last = solution;
                return margin;
            }
        }
    }
}
