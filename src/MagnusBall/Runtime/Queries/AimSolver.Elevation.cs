// AimSolver, part: the elevation solves (MinimumElevationToClearCore, ElevationToReachCore, SolveElevation) and the
// root finder every one-variable solve uses (SolveFromGuess: secant steps from the vacuum's guess to a bracket, then
// Illinois regula falsi). The public entry points are in AimSolver.cs.
using System;

namespace MagnusBall.Queries
{
    public sealed partial class AimSolver
    {
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
            _trials.StartSolve(SolveBudget);
            return SolveElevation(goal, speed, azimuthRadians, path, double.NaN, false, out _);
        }

        private AimSolution ElevationToReachCore(
            in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double azimuthFromTargetRadians, AimArc arc, in AimObstacle obstacle,
            int? viaShapeId)
        {
            CheckTarget(position, target);
            Require.Positive(speed, nameof(speed));
            Require.Finite(azimuthFromTargetRadians, nameof(azimuthFromTargetRadians));
            CheckArc(arc);
            AimGoal goal = TargetGoal(position, target, spin);
            AimGoal wall = obstacle.IsNone ? default : ObstacleGoal(goal, obstacle);
            goal = ViaGoal(goal, viaShapeId);
            _trials.StartSolve(SolveBudget);
            double path = PathToTarget(goal, azimuthFromTargetRadians);
            AimSolution s = SolveElevation(goal, speed, azimuthFromTargetRadians, path, double.NaN, arc == AimArc.High, out _);
            if (!Checks(obstacle))
            {
                return s;
            }

            s = CheckAll(s, goal, obstacle, wall);
            if (s.Status == AimStatus.Blocked && arc == AimArc.Low)
            {
                // The flat solution hits the obstacle: the lowest one that clears it is the lob, where it does.
                _trials.RestartFirstStep(); // the lob's trials as a lob solve's own
                AimSolution lob = CheckAll(SolveElevation(goal, speed, azimuthFromTargetRadians, path, double.NaN, true, out _), goal, obstacle, wall);
                return lob.Status == AimStatus.Solved || lob.Status == AimStatus.Blocked ? lob : WithFlights(s);
            }

            return s;
        }

        private static void CheckArc(AimArc arc)
        {
            if (arc != AimArc.Low && arc != AimArc.High)
            {
                throw new ArgumentOutOfRangeException(nameof(arc), arc, $"arc must be AimArc.Low or AimArc.High; got {(int)arc}.");
            }
        }

        /// <summary>
        /// The fast path of a one-parameter solve: secant steps from the vacuum's guess to the root. With adaptive trials,
        /// first on coarse trials to <see cref="CoarseFactor"/> times the tolerance, then moved onto the full trials
        /// (<see cref="AimRoots.TryPolish"/>, usually two trials); where that does not settle, secant steps on the full trials.
        /// </summary>
        private bool SolveFromGuess<T>(
            ref T margin, double guess, double slope, double min, double max, double stride, double tolerance, out double root, out AimSolution atRoot)
            where T : struct, IAimMargin
        {
            var noProbe = new ElevationMargin();
            return SolveFromGuess(ref margin, guess, slope, min, max, stride, tolerance, ref noProbe, false, out root, out atRoot, out _);
        }

        /// <summary>
        /// <see cref="SolveFromGuess{T}(ref T, double, double, double, double, double, double, out double, out AimSolution)"/>,
        /// and where the coarse trials fail to find the root and <paramref name="probe"/> is set, the reach probe on
        /// <paramref name="elevation"/> before the full trials try: <paramref name="outOfReach"/> (with the probe's best
        /// trial in <paramref name="atRoot"/>) when it finds the target out of reach.
        /// </summary>
        private bool SolveFromGuess<T>(
            ref T margin, double guess, double slope, double min, double max, double stride, double tolerance,
            ref ElevationMargin elevation, bool probe, out double root, out AimSolution atRoot, out bool outOfReach)
            where T : struct, IAimMargin
        {
            outOfReach = false;
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
                else if (probe && !ProbeReaches(ref elevation, out atRoot))
                {
                    // The coarse trials found no root, and the probe no trial that reaches: out of reach, without the full
                    // trials' secant steps (up to MaximumSecantSteps more flights).
                    root = double.NaN;
                    outOfReach = true;
                    return false;
                }
            }

            return AimRoots.TrySecant(ref margin, guess, slope, min, max, stride, tolerance, out root, out atRoot, out _);
        }

        /// <summary>
        /// The elevation at the edge of the arc asked for whose trial margin is &gt;= 0, at a fixed speed and azimuth: the lowest
        /// (<paramref name="high"/> false) or the highest, the lob. Near a hint (the azimuth search's last elevation) by a small
        /// bracket; else the arc's own limit when it works, the fast path from the vacuum's elevation on that arc over
        /// <paramref name="path"/> metres (the high arc on the mirrored margin, which grows through the root), or the scan
        /// from the arc's limit toward the other. Each bracket is (the failing end, the working end), as AimRoots.Refine takes it.
        /// </summary>
        private AimSolution SolveElevation(in AimGoal goal, double speed, double azimuth, double path, double hint, bool high, out double elevation)
        {
            var margin = new ElevationMargin(_trials, goal, speed, azimuth);
            double fail, failMargin, works, worksMargin;
            AimSolution atFail, atWorks;
            if (double.IsFinite(hint))
            {
                // Near a previous solution (the azimuth search moves it a little): try a small bracket first.
                double width = ElevationScanRadians;
                double lo = Math.Max(MinimumElevationRadians, hint - width);
                double hi = Math.Min(MaximumElevationRadians, hint + width);
                fail = high ? hi : lo;
                works = high ? lo : hi;
                failMargin = margin.Evaluate(fail, out _);
                if (failMargin < 0)
                {
                    worksMargin = margin.Evaluate(works, out atWorks);
                    if (worksMargin >= 0)
                    {
                        elevation = AimRoots.Refine(ref margin, fail, failMargin, works, worksMargin, ref atWorks, AngleTolerance, out _);
                        return WithFlights(atWorks);
                    }
                }
            }

            fail = high ? MaximumElevationRadians : MinimumElevationRadians;
            failMargin = margin.Evaluate(fail, out atFail);
            if (failMargin >= 0)
            {
                // Even the arc's limit does it: report that limit.
                elevation = fail;
                return WithFlights(atFail);
            }

            // The reach probe's golden sections look for one hump of the margin: a bank shot's (which banks in a window of
            // elevations and fails outside it) can hide from them, so its solve goes to the scan instead.
            bool probe = !goal.HasVia;
            bool probed = _trials.HasCoarse && probe; // with coarse trials, SolveFromGuess probes where the coarse secant fails
            bool solved, outOfReach;
            double root;
            AimSolution atRoot;
            if (high)
            {
                double guess = VacuumAim.HighElevation(_gravity, speed, path, goal.Rise, out double slope);
                var mirrored = new MirroredMargin<ElevationMargin>(margin);
                solved = SolveFromGuess(ref mirrored, -guess, -slope, -MaximumElevationRadians, -MinimumElevationRadians, AngleStride, AngleTolerance,
                    ref margin, probe, out root, out atRoot, out outOfReach);
                root = -root;
            }
            else
            {
                double guess = VacuumAim.LowElevation(_gravity, speed, path, goal.Rise, out double slope);
                solved = SolveFromGuess(ref margin, guess, slope, MinimumElevationRadians, MaximumElevationRadians, AngleStride, AngleTolerance,
                    ref margin, probe, out root, out atRoot, out outOfReach);
            }

            if (solved)
            {
                elevation = root;
                return WithFlights(atRoot);
            }

            if (outOfReach || (!probed && probe && !ProbeReaches(ref margin, out _)))
            {
                elevation = double.NaN;
                return Unreachable(speed, azimuth);
            }

            // The scan from the arc's limit toward the other: bounded by MaximumScanTrials (the constructor checks the scan width).
            double far = high ? MinimumElevationRadians : MaximumElevationRadians;
            for (int i = 1; ; i++)
            {
                works = high
                    ? Math.Max(MinimumElevationRadians, MaximumElevationRadians - i * ElevationScanRadians)
                    : Math.Min(MaximumElevationRadians, MinimumElevationRadians + i * ElevationScanRadians);
                worksMargin = margin.Evaluate(works, out atWorks);
                if (worksMargin >= 0)
                {
                    elevation = AimRoots.Refine(ref margin, fail, failMargin, works, worksMargin, ref atWorks, AngleTolerance, out _);
                    return WithFlights(atWorks);
                }

                if (works == far)
                {
                    break;
                }

                fail = works;
                failMargin = worksMargin;
            }

            elevation = double.NaN;
            return Unreachable(speed, azimuth);
        }

        /// <summary>
        /// The cheap test of reach before the scan: a golden-section search for the elevation with the largest margin over the
        /// limits, <see cref="ProbeTrials"/> trials (coarse where the trials have a coarse method). False, with that best
        /// trial, when even it comes short by more than <see cref="ProbeSlack"/>: the target is out of reach at this speed. A margin with two separate humps whose higher one the search does not
        /// see can be missed, as the scan can miss a window narrower than its width.
        /// </summary>
        private bool ProbeReaches(ref ElevationMargin margin, out AimSolution best)
        {
            const double InverseGolden = 0.6180339887498949;
            bool coarse = _trials.Coarse;
            _trials.Coarse = _trials.HasCoarse;
            double a = MinimumElevationRadians, b = MaximumElevationRadians;
            double c = b - InverseGolden * (b - a), d = a + InverseGolden * (b - a);
            double fc = margin.Evaluate(c, out AimSolution sc), fd = margin.Evaluate(d, out AimSolution sd);
            for (int i = 2; i < ProbeTrials && !(fc >= -ProbeSlack) && !(fd >= -ProbeSlack); i++)
            {
                if (fc >= fd || double.IsNaN(fd))
                {
                    b = d;
                    d = c;
                    fd = fc;
                    sd = sc;
                    c = b - InverseGolden * (b - a);
                    fc = margin.Evaluate(c, out sc);
                }
                else
                {
                    a = c;
                    c = d;
                    fc = fd;
                    sc = sd;
                    d = a + InverseGolden * (b - a);
                    fd = margin.Evaluate(d, out sd);
                }
            }

            _trials.Coarse = coarse;
            best = fc >= fd || double.IsNaN(fd) ? sc : sd;
            return fc >= -ProbeSlack || fd >= -ProbeSlack || _trials.WorkLimitReached;
        }

        /// <summary>The mirror image of a margin, x -&gt; f(-x): a falling root (the lob's) as a rising one for the root finders.</summary>
        private struct MirroredMargin<T> : IAimMargin
            where T : struct, IAimMargin
        {
            private T _inner;

            public MirroredMargin(in T inner) => _inner = inner;

            public double Evaluate(double x, out AimSolution solution) => _inner.Evaluate(-x, out solution);
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
    }
}
