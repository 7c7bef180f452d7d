using System;
using MagnusBall.Integration;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Locates the landing (first downward crossing of height 0 along up) inside one step, on the cubic Hermite
    /// through the step's end states and end velocities. The one place to swap for the queries API
    /// (HermiteSegment.TryFindCrossing) once it is on main.
    /// </summary>
    internal static class LandingLocator
    {
        public static bool TryLocate(in FlightState start, in FlightState end, in Vector3d up, double step, out Vector3d landing, out double time)
        {
            double f0 = Vector3d.Dot(start.Position, up);
            double f1 = Vector3d.Dot(end.Position, up);
            if (!(f0 >= 0 && f1 < 0))
            {
                landing = default;
                time = double.NaN;
                return false;
            }

            double d0 = Vector3d.Dot(start.Velocity, up) * step;
            double d1 = Vector3d.Dot(end.Velocity, up) * step;

            // Bisection on the height cubic, then polish: 80 halvings reach double precision in theta.
            double lo = 0, hi = 1;
            for (int i = 0; i < 80 && hi - lo > 1e-16; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (Height(f0, f1, d0, d1, mid) >= 0)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            double theta = 0.5 * (lo + hi);
            landing = Position(start, end, step, theta);
            time = start.Time + theta * step;
            return true;
        }

        private static double Height(double f0, double f1, double d0, double d1, double t)
        {
            double t2 = t * t, t3 = t2 * t;
            return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * d1;
        }

        private static Vector3d Position(in FlightState a, in FlightState b, double h, double t)
        {
            double t2 = t * t, t3 = t2 * t;
            return a.Position * (2 * t3 - 3 * t2 + 1) + a.Velocity * ((t3 - 2 * t2 + t) * h) + b.Position * (-2 * t3 + 3 * t2) + b.Velocity * ((t3 - t2) * h);
        }
    }

    /// <summary>Fixed-step and reference flights to the landing.</summary>
    internal static class Flight
    {
        /// <summary>Flies with a fixed step until the landing; evaluations count every derivative evaluation.</summary>
        public static bool TryLand(
            FlightModel model, IIntegrator integrator, FlightState state, double step, double maxTime, out Vector3d landing, out long evaluations)
        {
            StateDerivative derivative = model.Derivative(state);
            evaluations = 1;
            int perStep = integrator.DerivativeEvaluationsPerStep;
            while (state.Time < maxTime)
            {
                FlightState next = integrator.Step(model, state, derivative, step);
                evaluations += perStep;
                if (LandingLocator.TryLocate(state, next, Scenarios.Up, step, out landing, out _))
                {
                    return true;
                }

                state = next;
                derivative = model.Derivative(state);
            }

            landing = default;
            return false;
        }

        /// <summary>As <see cref="TryLand"/>, through <see cref="StableStepping.Step"/> (the default, safe stepping).</summary>
        public static bool TryLandStable(
            FlightModel model, IIntegrator integrator, FlightState state, double step, double maxTime, out Vector3d landing, out long evaluations)
        {
            StateDerivative derivative = model.Derivative(state);
            evaluations = 1;
            int perStep = integrator.DerivativeEvaluationsPerStep;
            while (state.Time < maxTime)
            {
                FlightState next = StableStepping.Step(integrator, model, state, derivative, step, out StateDerivative end, out int substeps);
                evaluations += (long)perStep * substeps;
                if (LandingLocator.TryLocate(state, next, Scenarios.Up, step, out landing, out _))
                {
                    return true;
                }

                state = next;
                derivative = end;
            }

            landing = default;
            return false;
        }

        /// <summary>
        /// The reference landing: adaptive Dormand-Prince 5(4) at rtol = atol = <paramref name="tolerance"/>, the crossing
        /// located by bisection on its own fourth-order dense output.
        /// </summary>
        public static bool TryLandReference(FlightModel model, FlightState state, double maxTime, double tolerance, out Vector3d landing, out long evaluations)
        {
            var method = new DormandPrince54(tolerance, tolerance);
            StateDerivative derivative = model.Derivative(state);
            double step = method.InitialStep(model, state, derivative, 0.01);
            evaluations = 2;
            while (state.Time < maxTime)
            {
                bool accepted = method.TryStep(model, state, derivative, step, out DormandPrince54Step result);
                evaluations += 6;
                step = result.NextStep;
                if (!accepted)
                {
                    continue;
                }

                double h0 = Vector3d.Dot(result.Start.Position, Scenarios.Up);
                double h1 = Vector3d.Dot(result.End.Position, Scenarios.Up);
                if (h0 >= 0 && h1 < 0)
                {
                    double lo = 0, hi = 1;
                    for (int i = 0; i < 80 && hi - lo > 1e-16; i++)
                    {
                        double mid = 0.5 * (lo + hi);
                        if (Vector3d.Dot(result.InterpolateFraction(mid).Position, Scenarios.Up) >= 0)
                        {
                            lo = mid;
                        }
                        else
                        {
                            hi = mid;
                        }
                    }

                    landing = result.InterpolateFraction(0.5 * (lo + hi)).Position;
                    return true;
                }

                state = result.End;
                derivative = result.EndDerivative;
            }

            landing = default;
            return false;
        }
    }
}
