// SwingAim, part: the solve shared by the four inverses (Solve, a Broyden iteration on two swing angles, each residual an
// AimSolver solve within the call's work budget). The public inverses and the budget are in SwingAim.cs.
using System;
using MagnusBall.Contact.Swings;

namespace MagnusBall.Queries
{
    public sealed partial class SwingAim
    {
        /// <summary>The two adjustable angles of a swing, in degrees, and the launch they give.</summary>
        private interface IFamily<TSwing>
            where TSwing : struct
        {
            bool InRange(double x1, double x2);

            TSwing With(double x1, double x2);

            SwingLaunch Hit(in TSwing swing);
        }

        private SwingSolution<TSwing> Solve<TSwing, TFamily>(
            ref TFamily family, in LaunchFrame aimFrame, double x1, double x2, in Vector3d position, in Vector3d target, double maximumAzimuthDegrees)
            where TSwing : struct
            where TFamily : struct, IFamily<TSwing>
        {
            LastWork = 0;
            _budgetReached = false;
            try
            {
                SwingSolution<TSwing> s = Broyden<TSwing, TFamily>(ref family, aimFrame, x1, x2, position, target, maximumAzimuthDegrees);
                return _budgetReached && !s.IsSolved
                    ? new SwingSolution<TSwing>(AimStatus.WorkLimitReached, s.Swing, s.Launch, s.Aim, s.Iterations)
                    : s;
            }
            finally
            {
                Solver.BudgetCap = long.MaxValue;
            }
        }

        private SwingSolution<TSwing> Broyden<TSwing, TFamily>(
            ref TFamily family, in LaunchFrame aimFrame, double x1, double x2, in Vector3d position, in Vector3d target, double maximumAzimuthDegrees)
            where TSwing : struct
            where TFamily : struct, IFamily<TSwing>
        {
            TSwing current = family.With(x1, x2);
            if (!Residual<TSwing, TFamily>(ref family, current, aimFrame, position, target, maximumAzimuthDegrees,
                    out SwingLaunch launch, out AimSolution aim, out double r1, out double r2))
            {
                return new SwingSolution<TSwing>(AimStatus.Unreachable, current, launch, aim, 1);
            }

            // Broyden's method on r(x) = aim angles - launch angles, x = the two angles in degrees, started from the
            // Jacobian of -launch angles (central differences of the swing alone: the aim's own response to speed and
            // spin is learnt by the updates), with backtracking when a step makes the residual worse or unreachable.
            if (!LaunchJacobian<TSwing, TFamily>(ref family, x1, x2, aimFrame, out double j11, out double j12, out double j21, out double j22))
            {
                return new SwingSolution<TSwing>(AimStatus.Unreachable, current, launch, aim, 1);
            }

            j11 = -j11; j12 = -j12; j21 = -j21; j22 = -j22;
            // The residual's norm after each accepted step, for the stall test (a ring of the last StallIterations + 1).
            Span<double> norms = stackalloc double[StallIterations + 1];
            norms[0] = Math.Sqrt(r1 * r1 + r2 * r2);
            for (int iteration = 1; iteration <= MaximumIterations; iteration++)
            {
                if (Math.Abs(r1) <= AngleTolerance && Math.Abs(r2) <= AngleTolerance)
                {
                    return new SwingSolution<TSwing>(AimStatus.Solved, current, launch, aim, iteration);
                }

                if (_budgetReached)
                {
                    break;
                }

                if (iteration > StallIterations && !(norms[(iteration - 1) % norms.Length] <= StallRatio * norms[(iteration - 1 - StallIterations) % norms.Length]))
                {
                    // The residual stopped shrinking: the swing creeps along the edge of its reach (a target too far for
                    // its speed). Say so now rather than after MaximumIterations steps of up to MaximumHalvings solves each.
                    return new SwingSolution<TSwing>(AimStatus.Unreachable, current, launch, aim, iteration);
                }

                double determinant = j11 * j22 - j12 * j21;
                if (!(Math.Abs(determinant) > 1e-300) || !double.IsFinite(determinant))
                {
                    break;
                }

                // Newton step: J dx = -r.
                double dx1 = -(r1 * j22 - r2 * j12) / determinant;
                double dx2 = -(j11 * r2 - j21 * r1) / determinant;
                double norm = Math.Sqrt(r1 * r1 + r2 * r2);
                bool accepted = false;
                int outOfReach = 0; // trial swings whose launch the aim solver could not bring to the target
                double scale = 1;
                for (int halving = 0; halving < MaximumHalvings && !accepted; halving++, scale *= 0.5)
                {
                    double t1 = x1 + scale * dx1, t2 = x2 + scale * dx2;
                    if (!family.InRange(t1, t2))
                    {
                        continue;
                    }

                    TSwing trial = family.With(t1, t2);
                    if (!Residual<TSwing, TFamily>(ref family, trial, aimFrame, position, target, maximumAzimuthDegrees,
                            out SwingLaunch trialLaunch, out AimSolution trialAim, out double s1, out double s2))
                    {
                        outOfReach += trialAim.Status == AimStatus.Unreachable ? 1 : 0;
                        continue;
                    }

                    if (Math.Sqrt(s1 * s1 + s2 * s2) >= norm && halving < MaximumHalvings - 1)
                    {
                        continue;
                    }

                    // Broyden update with the step taken (degrees) and the change of the residual (rad).
                    double h1 = scale * dx1, h2 = scale * dx2, hh = h1 * h1 + h2 * h2;
                    double y1 = s1 - r1 - (j11 * h1 + j12 * h2), y2 = s2 - r2 - (j21 * h1 + j22 * h2);
                    if (hh > 0)
                    {
                        j11 += y1 * h1 / hh; j12 += y1 * h2 / hh; j21 += y2 * h1 / hh; j22 += y2 * h2 / hh;
                    }

                    x1 = t1;
                    x2 = t2;
                    current = trial;
                    launch = trialLaunch;
                    aim = trialAim;
                    r1 = s1;
                    r2 = s2;
                    accepted = true;
                }

                norms[iteration % norms.Length] = Math.Sqrt(r1 * r1 + r2 * r2);
                if (accepted && outOfReach >= EdgeTrials && !(norms[iteration % norms.Length] <= (1 - EdgeProgress) * norm))
                {
                    // The Newton step led out of reach, and the step back inside barely helped: the swing sits at the edge
                    // of its reach, short of the target (a flag too far for the club's speed). Say so after this one step.
                    return new SwingSolution<TSwing>(AimStatus.Unreachable, current, launch, aim, iteration + 1);
                }

                if (!accepted || _budgetReached)
                {
                    break;
                }
            }

            return new SwingSolution<TSwing>(AimStatus.Unreachable, current, launch, aim, MaximumIterations);
        }

        // One aim solve within what is left of the call's budget (at least the solver's smallest budget: the last solve may
        // overrun the call's budget by that much).
        private AimSolution Aim(in Vector3d position, double speed, in LaunchSpin spin, in Vector3d target, double maximumAzimuthDegrees)
        {
            Solver.BudgetCap = Math.Max(AimSolver.MinimumEvaluationsPerSolve, MaximumEvaluations - LastWork);
            AimSolution aim = Solver.AnglesToReach(position, speed, spin, target, maximumAzimuthDegrees);
            LastWork += Solver.LastWork;
            if (aim.Status == AimStatus.WorkLimitReached || LastWork >= MaximumEvaluations)
            {
                _budgetReached = true;
            }

            return aim;
        }

        private bool Residual<TSwing, TFamily>(
            ref TFamily family, in TSwing swing, in LaunchFrame aimFrame, in Vector3d position, in Vector3d target, double maximumAzimuthDegrees,
            out SwingLaunch launch, out AimSolution aim, out double elevationError, out double azimuthError)
            where TSwing : struct
            where TFamily : struct, IFamily<TSwing>
        {
            elevationError = azimuthError = double.NaN;
            aim = default;
            launch = new SwingLaunch(family.Hit(swing).Impact, aimFrame);
            if (!launch.IsHit || !(launch.Speed > 0))
            {
                return false;
            }

            if (_budgetReached)
            {
                return false;
            }

            aim = Aim(position, launch.Speed, launch.LaunchSpin, target, maximumAzimuthDegrees);
            if (!aim.IsSolved || !(Miss(aim, position, target) <= MissTolerance))
            {
                return false;
            }

            elevationError = Wrap(aim.ElevationRadians - launch.ElevationRadians);
            azimuthError = Wrap(aim.AzimuthFromTargetRadians - launch.AzimuthRadians);
            return true;
        }

        // The aim solution's miss as MissTolerance judges it: its distance from the target, or for a target below the ground
        // (launched from on or above it) its landing's distance along the ground from the point over the target.
        private double Miss(in AimSolution aim, in Vector3d position, in Vector3d target)
        {
            Plane ground = Solver.Ground;
            if (!(ground.SignedDistance(target) < 0) || !(ground.SignedDistance(position) >= 0))
            {
                return aim.Miss;
            }

            Vector3d d = aim.Arrival.Position - target;
            return (d - ground.Normal * Vector3d.Dot(d, ground.Normal)).Length;
        }

        private static bool LaunchJacobian<TSwing, TFamily>(
            ref TFamily family, double x1, double x2, in LaunchFrame aimFrame, out double j11, out double j12, out double j21, out double j22)
            where TSwing : struct
            where TFamily : struct, IFamily<TSwing>
        {
            j11 = j12 = j21 = j22 = 0;
            if (!TryAngles<TSwing, TFamily>(ref family, x1 + DifferenceDegrees, x2, aimFrame, out double e1, out double a1) ||
                !TryAngles<TSwing, TFamily>(ref family, x1 - DifferenceDegrees, x2, aimFrame, out double e2, out double a2) ||
                !TryAngles<TSwing, TFamily>(ref family, x1, x2 + DifferenceDegrees, aimFrame, out double e3, out double a3) ||
                !TryAngles<TSwing, TFamily>(ref family, x1, x2 - DifferenceDegrees, aimFrame, out double e4, out double a4))
            {
                return false;
            }

            double h = 2 * DifferenceDegrees;
            j11 = (e1 - e2) / h;
            j21 = Wrap(a1 - a2) / h;
            j12 = (e3 - e4) / h;
            j22 = Wrap(a3 - a4) / h;
            return true;
        }

        private static bool TryAngles<TSwing, TFamily>(
            ref TFamily family, double x1, double x2, in LaunchFrame aimFrame, out double elevation, out double launchAzimuth)
            where TSwing : struct
            where TFamily : struct, IFamily<TSwing>
        {
            elevation = launchAzimuth = 0;
            if (!family.InRange(x1, x2))
            {
                return false;
            }

            var launch = new SwingLaunch(family.Hit(family.With(x1, x2)).Impact, aimFrame);
            if (!launch.IsHit)
            {
                return false;
            }

            elevation = launch.ElevationRadians;
            launchAzimuth = launch.AzimuthRadians;
            return true;
        }

        private static double Wrap(double angle) =>
            angle > Math.PI ? angle - 2 * Math.PI : angle < -Math.PI ? angle + 2 * Math.PI : angle;

        private static bool Within(double value, double low, double high) => value >= low && value <= high;
    }
}
