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
            _trials.StartSolve();
            return SolveElevation(goal, speed, azimuthRadians, path, double.NaN, out _);
        }

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
