using System;
using MagnusBall.Integration;
using MagnusBall.Queries;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Locates the landing (first crossing of the ground plane through the origin, against up) inside one step, on the
    /// cubic Hermite of the step: the queries API's <see cref="HermiteSegment.TryFindCrossing"/>.
    /// </summary>
    internal static class LandingLocator
    {
        public static readonly Plane Ground = new Plane(default, Scenarios.Up);

        public static bool TryLocate(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative, out Vector3d landing)
        {
            var segment = new HermiteSegment(start, startDerivative, end, endDerivative);
            if (segment.TryFindCrossing(Ground, CrossingDirection.AgainstNormal, out double time))
            {
                landing = segment.PositionAt(time);
                return true;
            }

            landing = default;
            return false;
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
                StateDerivative end = model.Derivative(next);
                evaluations += perStep;
                if (LandingLocator.TryLocate(state, derivative, next, end, out landing))
                {
                    return true;
                }

                state = next;
                derivative = end;
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
                if (LandingLocator.TryLocate(state, derivative, next, end, out landing))
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
        public static bool TryLandReference(FlightModel model, FlightState state, double maxTime, double tolerance, out Vector3d landing, out long evaluations) =>
            TryLandReference(model, state, maxTime, new DormandPrince54(tolerance, tolerance), out landing, out evaluations);

        /// <summary>As above, with a given method (no allocation).</summary>
        public static bool TryLandReference(FlightModel model, FlightState state, double maxTime, DormandPrince54 method, out Vector3d landing, out long evaluations)
        {
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
