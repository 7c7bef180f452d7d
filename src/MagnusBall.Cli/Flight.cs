using System;
using System.Collections.Generic;

namespace MagnusBall.Cli
{
    /// <summary>A plane crossing: which plane, the state there, and (for a bounded plane) whether it passed inside.</summary>
    internal sealed record Crossing(string Name, FlightState State, bool? Inside);

    /// <summary>One integrator step's end: the state and the derivative there (what the Hermite needs).</summary>
    internal readonly record struct StepPoint(FlightState State, StateDerivative Derivative);

    /// <summary>What one scenario's flight found.</summary>
    internal sealed record FlightResult(
        Scenario Scenario,
        FlightState? Landing,
        FlightState? Apex,
        IReadOnlyList<Crossing> Crossings,
        int Steps,
        long DerivativeEvaluations,
        FlightState End,
        IReadOnlyList<StepPoint>? Points)
    {
        /// <summary>
        /// The state at <paramref name="time"/> (clamped to the flight) on the cubic Hermite of the step
        /// containing it. Needs the recorded step points.
        /// </summary>
        public FlightState At(double time)
        {
            IReadOnlyList<StepPoint> points = Points ?? throw new InvalidOperationException("steps were not recorded");
            if (time <= points[0].State.Time)
            {
                return points[0].State;
            }

            if (time >= End.Time)
            {
                return End;
            }

            int lo = 0, hi = points.Count - 1;
            while (hi - lo > 1)
            {
                int mid = (lo + hi) / 2;
                if (points[mid].State.Time <= time)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            StepPoint a = points[lo], b = points[hi];
            return StepEvents.Interpolate(a.State, a.Derivative, b.State, b.Derivative, time);
        }
    }

    /// <summary>
    /// Flies a <see cref="Scenario"/> with its integrator at its fixed step until it lands (first crossing of
    /// the ground plane against its normal) or reaches maxTime, locating the apex and every plane crossing
    /// between steps on the cubic Hermite interpolant.
    /// </summary>
    internal static class Flight
    {
        public static FlightResult Simulate(Scenario scenario, bool recordSteps)
        {
            var model = scenario.Model;
            var integrator = scenario.Integrator;
            Vector3d up = model.Up;
            double endTime = scenario.Initial.Time + scenario.MaxTime;

            FlightState state = scenario.Initial;
            StateDerivative derivative = model.Derivative(state);
            long evaluations = 1;
            int steps = 0;
            var points = recordSteps ? new List<StepPoint> { new StepPoint(state, derivative) } : null;
            var crossings = new List<Crossing>();
            FlightState? apex = null;
            FlightState? landing = null;

            while (state.Time < endTime && landing is null)
            {
                // Fixed steps; the last one is shortened to end exactly at maxTime.
                double h = Math.Min(scenario.Step, endTime - state.Time);
                if (!(h > 1e-9 * scenario.Step))
                {
                    break;
                }

                FlightState next = integrator.Step(model, state, derivative, h);
                if (!next.IsFinite)
                {
                    throw new InputError(
                        PathOfStep(scenario),
                        $"the flight diverged (non-finite state after t = {JsonFields.Format(state.Time)} s with {integrator.Name}); use a smaller step");
                }

                StateDerivative nextDerivative = model.Derivative(next);
                evaluations += integrator.DerivativeEvaluationsPerStep;
                steps++;

                double stepEnd = next.Time;
                if (scenario.Ground is NamedPlane ground &&
                    StepEvents.TryPlaneCrossing(state, derivative, next, nextDerivative, ground.Point, ground.Normal, along: false, out FlightState touch))
                {
                    landing = touch;
                    stepEnd = touch.Time;
                }

                if (apex is null && up.LengthSquared > 0 &&
                    StepEvents.TryApex(state, derivative, next, nextDerivative, up, out FlightState top) && top.Time <= stepEnd)
                {
                    apex = top;
                }

                int firstNew = crossings.Count;
                foreach (NamedPlane plane in scenario.Planes)
                {
                    if (StepEvents.TryPlaneCrossing(state, derivative, next, nextDerivative, plane.Point, plane.Normal, along: true, out FlightState at) &&
                        at.Time <= stepEnd)
                    {
                        crossings.Add(new Crossing(plane.Name, at, plane.Bounds?.Contains(at.Position, plane.Point)));
                    }
                }

                if (crossings.Count - firstNew > 1)
                {
                    crossings.Sort(firstNew, crossings.Count - firstNew, Comparer<Crossing>.Create((a, b) => a.State.Time.CompareTo(b.State.Time)));
                }

                state = next;
                derivative = nextDerivative;
                points?.Add(new StepPoint(state, derivative));
            }

            // The last step point may lie past the landing: it stays for the interpolant, but the flight ends at the landing.
            FlightState end = landing ?? state;
            return new FlightResult(scenario, landing, apex, crossings, steps, evaluations, end, points);
        }

        private static string PathOfStep(Scenario scenario) => $"scenarios[{scenario.Index}].step";
    }
}
