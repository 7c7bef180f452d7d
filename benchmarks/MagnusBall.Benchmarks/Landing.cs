using System;
using MagnusBall.Flight;
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

    /// <summary>Fixed-step and reference flights to the landing, through the library's one flight core.</summary>
    internal static class Flight
    {
        /// <summary>The ground through the origin, no apex: the landing is the only event.</summary>
        private static readonly FlightEventSet GroundOnly = new FlightEventSet(Vector3d.Zero, LandingLocator.Ground);

        /// <summary>Flies with a fixed step until the landing; evaluations count every model evaluation.</summary>
        public static bool TryLand(
            FlightModel model, IIntegrator integrator, FlightState state, double step, double maxTime, out Vector3d landing, out long evaluations) =>
            Fly(new FlightStepper(model, integrator, GroundOnly), state, step, maxTime, out landing, out evaluations);

        /// <summary>As <see cref="TryLand"/>, substepped for stability (<see cref="StableIntegrator"/>, the default, safe stepping).</summary>
        public static bool TryLandStable(
            FlightModel model, IIntegrator integrator, FlightState state, double step, double maxTime, out Vector3d landing, out long evaluations) =>
            Fly(new FlightStepper(model, new StableIntegrator(integrator), GroundOnly), state, step, maxTime, out landing, out evaluations);

        private static bool Fly(FlightStepper stepper, FlightState state, double step, double maxTime, out Vector3d landing, out long evaluations)
        {
            stepper.Reset(state);
            // Bounded: each pass advances the clock by a step, or ends.
            while (stepper.State.Time < maxTime && stepper.TryStep(step, FlightEventKinds.Landing) != StepOutcome.Diverged)
            {
                if (stepper.IsStopped)
                {
                    landing = stepper.StopEvent.Position;
                    evaluations = stepper.DerivativeEvaluations;
                    return true;
                }
            }

            landing = default;
            evaluations = stepper.DerivativeEvaluations;
            return false;
        }

        /// <summary>
        /// The reference landing: adaptive Dormand-Prince 5(4) at rtol = atol = <paramref name="tolerance"/>, the crossing
        /// located on its own fourth-order dense output by the flight core.
        /// </summary>
        public static bool TryLandReference(FlightModel model, FlightState state, double maxTime, double tolerance, out Vector3d landing, out long evaluations) =>
            TryLandReference(new FlightStepper(model, RungeKutta4.Instance, GroundOnly), state, maxTime, new DormandPrince54(tolerance, tolerance), out landing, out evaluations);

        /// <summary>As above, with a given stepper and method (no allocation).</summary>
        public static bool TryLandReference(FlightStepper stepper, FlightState state, double maxTime, DormandPrince54 method, out Vector3d landing, out long evaluations)
        {
            stepper.Reset(state);
            // Bounded: FlightStepper.MaxAdaptiveAttempts per step, and each accepted step advances the clock.
            while (stepper.State.Time < maxTime &&
                   stepper.TryStepAdaptive(method, maxTime - stepper.State.Time, FlightEventKinds.Landing) == StepOutcome.Taken)
            {
            }

            evaluations = stepper.DerivativeEvaluations;
            landing = stepper.IsStopped ? stepper.StopEvent.Position : default;
            return stepper.IsStopped;
        }

        /// <summary>A stepper for <see cref="TryLandReference(FlightStepper, FlightState, double, DormandPrince54, out Vector3d, out long)"/>.</summary>
        public static FlightStepper ReferenceStepper(FlightModel model) => new FlightStepper(model, RungeKutta4.Instance, GroundOnly);
    }
}
