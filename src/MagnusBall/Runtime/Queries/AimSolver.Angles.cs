// AimSolver, part: both angles at once (AnglesToReachCore): Broyden's method on elevation and azimuth from the vacuum's
// aim, and where it fails a search over the azimuth with an elevation solve at each. The public entry point,
// AnglesToReach, is in AimSolver.cs.
using System;

namespace MagnusBall.Queries
{
    public sealed partial class AimSolver
    {
        private AimSolution AnglesToReachCore(
            in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double maximumAzimuthDegrees, AimArc arc, in AimObstacle obstacle,
            int? viaShapeId)
        {
            CheckTarget(position, target);
            Require.Positive(speed, nameof(speed));
            Require.InRange(maximumAzimuthDegrees, double.Epsilon, 89, nameof(maximumAzimuthDegrees));
            CheckArc(arc);
            double limit = maximumAzimuthDegrees * (Math.PI / 180);
            AimGoal goal = TargetGoal(position, target, spin);
            AimGoal wall = obstacle.IsNone ? default : ObstacleGoal(goal, obstacle);
            goal = ViaGoal(goal, viaShapeId);
            _trials.StartSolve(SolveBudget);
            AimSolution s = BothAngles(goal, speed, limit, arc == AimArc.High);
            if (!Checks(obstacle))
            {
                return s;
            }

            s = CheckAll(s, goal, obstacle, wall);
            if (s.Status == AimStatus.Blocked && arc == AimArc.Low)
            {
                // The flat solution hits the obstacle: the lowest one that clears it is the lob, where it does.
                _trials.RestartFirstStep(); // the lob's trials as a lob solve's own
                AimSolution lob = CheckAll(BothAngles(goal, speed, limit, high: true), goal, obstacle, wall);
                return lob.Status == AimStatus.Solved || lob.Status == AimStatus.Blocked ? lob : WithFlights(s);
            }

            return s;
        }

        private AimSolution BothAngles(in AimGoal goal, double speed, double limit, bool high)
        {
            if (TryBothAngles(goal, speed, limit, high, out AimSolution solved, out bool ran))
            {
                return solved;
            }

            if (ran && _trials.HasCoarse)
            {
                // Broyden's method ran and failed: before the fallback's elevation solves, the reach probe toward the target
                // (the fallback's first azimuth), which tells a target out of reach at this speed in a dozen coarse trials.
                var toward = new ElevationMargin(_trials, goal, speed, 0);
                if (!ProbeReaches(ref toward, out _))
                {
                    return Unreachable(speed, 0);
                }
            }

            return AnglesByAzimuthSearch(goal, speed, limit, high);
        }

        /// <summary>
        /// Both angles at once: Broyden's method on r = (height margin at the target plane, sideways miss) over
        /// x = (elevation, azimuth), from the vacuum's lower elevation and azimuth 0 with the vacuum's Jacobian
        /// (diag(d height / d elevation, distance)). Converged when the next step is within <see cref="AngleTolerance"/>
        /// in both angles; accepted only on the drive side (the height grows with elevation), with the lower limit not
        /// working (else the lower limit is the answer, as the fallback finds) and within the limits.
        /// </summary>
        private bool TryBothAngles(in AimGoal goal, double speed, double azimuthLimit, bool high, out AimSolution solved, out bool ran)
        {
            solved = default;
            ran = false;
            double distance = Vector3d.DotOfDifference(goal.Target, goal.Position, goal.Frame.Forward);
            double e = high
                ? VacuumAim.HighElevation(_gravity, speed, distance, goal.Rise, out double slope)
                : VacuumAim.LowElevation(_gravity, speed, distance, goal.Rise, out slope);
            if (double.IsNaN(e) || !(high ? slope < 0 : slope > 0))
            {
                return false;
            }

            if (high && e > MaximumElevationRadians)
            {
                // The vacuum's lob is steeper than the real one (drag brings the ball down short): start at the upper
                // limit rather than give up (a 30 m/s tennis lob: 82 degrees in a vacuum, 72 in air).
                e = MaximumElevationRadians;
            }

            // The limit on the arc's side, at the azimuth toward the target: where it works, the fallback returns it.
            if (!(_trials.Margin(goal, speed, high ? MaximumElevationRadians : MinimumElevationRadians, 0, out _) < 0))
            {
                return false;
            }

            ran = true;
            _trials.Coarse = _trials.HasCoarse;
            bool found = Broyden(goal, speed, azimuthLimit, e, slope, distance, high, out solved);
            _trials.Coarse = false;
            return found;
        }

        // TryBothAngles's iteration: with adaptive trials first on coarse trials to CoarseFactor times the tolerance, then on
        // the full trials (the first full trial keeps the Jacobian as it is: the change of residual from a coarse to a full
        // trial is the two trials' difference, not the step's effect).
        private bool Broyden(in AimGoal goal, double speed, double azimuthLimit, double e, double slope, double distance, bool high, out AimSolution solved)
        {
            solved = default;
            double az = 0;
            double j11 = slope, j12 = 0, j21 = 0, j22 = distance;
            double r1 = 0, r2 = 0, dx1 = 0, dx2 = 0;
            bool update = false;
            // The residual's size at each trial, for the stall test (a ring of the last BroydenStallSteps + 1).
            Span<double> sizes = stackalloc double[BroydenStallSteps + 1];
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
                sizes[k % sizes.Length] = Math.Abs(m) + Math.Abs(lateral);
                if (k >= BroydenStallSteps && !(sizes[k % sizes.Length] <= 0.5 * sizes[(k - BroydenStallSteps) % sizes.Length]))
                {
                    // The residual stopped shrinking (a target out of reach at this speed: the trials creep along the edge
                    // of the reach): leave it to the fallback, whose elevation solve tells out of reach cheaply.
                    return false;
                }
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
                    // Converged at this trial (it is within the tolerance of the root), on the arc's side (the height grows with
                    // the elevation for the drive, falls for the lob), having arrived.
                    if (!(high ? j11 < 0 : j11 > 0) || !(s.Miss < ConvergedMiss))
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
        private AimSolution AnglesByAzimuthSearch(in AimGoal goal, double speed, double limit, bool high)
        {
            var lateral = new AzimuthMargin(this, goal, speed, high);
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

        private struct AzimuthMargin : IAimMargin
        {
            private readonly AimSolver _solver;
            private readonly AimGoal _goal;
            private readonly double _speed;
            private readonly bool _high;
            private double _hint;

            public AzimuthMargin(AimSolver solver, in AimGoal goal, double speed, bool high)
            {
                _solver = solver;
                _goal = goal;
                _speed = speed;
                _high = high;
                _hint = double.NaN;
            }

            /// <summary>The sideways miss (along the frame's side) after solving the elevation; NaN when no elevation reaches the height.</summary>
            public double Evaluate(double azimuth, out AimSolution solution)
            {
                solution = _solver.SolveElevation(_goal, _speed, azimuth, PathToTarget(_goal, azimuth), _hint, _high, out double elevation);
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
