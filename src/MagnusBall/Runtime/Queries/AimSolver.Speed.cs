// AimSolver, part: the speed solve (SpeedToReachCore): the launch speed that puts the ball through a target at a given
// elevation and azimuth, by SolveFromGuess (AimSolver.Elevation.cs), then a scan. The public entry point, SpeedToReach, is
// in AimSolver.cs.
using System;

namespace MagnusBall.Queries
{
    public sealed partial class AimSolver
    {
        private AimSolution SpeedToReachCore(
            in Vector3d position, double elevationRadians, double azimuthFromTargetRadians, in LaunchSpin spin, in Vector3d target, in AimObstacle obstacle,
            int? viaShapeId)
        {
            CheckTarget(position, target);
            AimGoal goal = TargetGoal(position, target, spin);
            AimGoal wall = obstacle.IsNone ? default : ObstacleGoal(goal, obstacle);
            goal = ViaGoal(goal, viaShapeId);
            AimSolution s = SpeedToReachCore(position, elevationRadians, azimuthFromTargetRadians, goal);
            return Checks(obstacle) ? CheckAll(s, goal, obstacle, wall) : s;
        }

        private AimSolution SpeedToReachCore(in Vector3d position, double elevationRadians, double azimuthFromTargetRadians, in AimGoal goal)
        {
            Require.InRange(elevationRadians, -0.5 * Math.PI + 1e-9, 0.5 * Math.PI - 1e-9, nameof(elevationRadians));
            Require.Finite(azimuthFromTargetRadians, nameof(azimuthFromTargetRadians));
            _trials.StartSolve(SolveBudget);
            var margin = new SpeedMargin(_trials, goal, elevationRadians, azimuthFromTargetRadians);
            double scan = 0.01 * MaximumSpeed;

            // The fast path: from the vacuum's speed, within [1 %, 100 %] of the maximum (below, the scan's crawl rule).
            double guess = VacuumAim.Speed(_gravity, elevationRadians, PathToTarget(goal, azimuthFromTargetRadians), goal.Rise, out double slope);
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

            return UnreachableSpeed(elevationRadians, azimuthFromTargetRadians);
        }

        private AimSolution UnreachableSpeed(double elevationRadians, double azimuthFromTargetRadians) =>
            new AimSolution(
                AimStatus.Unreachable, MaximumSpeed, elevationRadians, azimuthFromTargetRadians, default, default, default, double.PositiveInfinity, _trials.Flights);

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
    }
}
