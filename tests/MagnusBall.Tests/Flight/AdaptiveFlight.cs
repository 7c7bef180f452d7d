using System;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Flight
{
    /// <summary>Test helper: an adaptive flight over a duration through the one flight core.</summary>
    internal static class AdaptiveFlight
    {
        /// <summary>Flies <paramref name="duration"/> seconds with adaptive Dormand-Prince steps, ending exactly on the end time.</summary>
        public static FlightState Fly(DormandPrince54 method, FlightModel model, in FlightState start, double duration, out long evaluations)
        {
            var flight = new FlightStepper(model, RungeKutta4.Instance);
            FlightState end = Fly(flight, method, start, duration);
            evaluations = flight.DerivativeEvaluations;
            return end;
        }

        /// <summary>The same with a given stepper (for allocation tests).</summary>
        public static FlightState Fly(FlightStepper flight, DormandPrince54 method, in FlightState start, double duration)
        {
            flight.Reset(start);
            double endTime = start.Time + duration;
            // Bounded: 100,000 accepted steps are far more than any test flight needs.
            for (int i = 0; i < 100_000 && flight.State.Time < endTime; i++)
            {
                if (flight.TryStepAdaptive(method, endTime - flight.State.Time) != StepOutcome.Taken)
                {
                    Assert.Fail($"adaptive step refused at {flight.State}");
                }
            }

            return flight.State;
        }
    }
}
