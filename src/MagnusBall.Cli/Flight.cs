using System;
using System.Collections.Generic;
using System.Linq;
using MagnusBall.Queries;

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
            return new HermiteSegment(a.State, a.Derivative, b.State, b.Derivative).StateAt(time);
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
            FlightModel model = scenario.Model;
            double endTime = scenario.Initial.Time + scenario.MaxTime;

            // The library's shared stepping loop: each step's end derivative is the next step's start, the cubic
            // Hermite of the step costs nothing more, and the events are located on it to 1e-12 s.
            Plane? ground = scenario.Ground is NamedPlane g ? new Plane(g.Point, g.Normal) : null;
            var planes = scenario.Planes.Select(p => new Plane(p.Point, p.Normal)).ToArray();
            var stepper = new FlightStepper(model, scenario.Integrator, new FlightEventSet(model.Up, ground, planes));
            stepper.Reset(scenario.Initial);

            var points = recordSteps ? new List<StepPoint> { new StepPoint(stepper.State, stepper.Derivative) } : null;
            var crossings = new List<Crossing>();
            FlightState? apex = null;
            FlightState? landing = null;

            while (stepper.State.Time < endTime && landing is null)
            {
                // Fixed steps; the last one is shortened to end exactly at maxTime.
                double h = Math.Min(scenario.Step, endTime - stepper.State.Time);
                if (!(h > 1e-9 * scenario.Step))
                {
                    break;
                }

                double before = stepper.State.Time;
                // TryStep refuses a step that blows up (the state is kept), so the error can name the step.
                if (!stepper.TryStep(h) || !stepper.State.IsFinite)
                {
                    throw new InputError(
                        $"scenarios[{scenario.Index}].step",
                        $"the flight diverged (non-finite state after t = {JsonFields.Format(before)} s with {scenario.Integrator.Name}); use a smaller step");
                }

                // Events come in time order; nothing after the landing counts (the library's one rule for it).
                ReadOnlySpan<FlightEvent> events = stepper.EventsUntil(FlightEventKinds.Landing, out bool landed, out FlightEvent touchdown);
                if (landed)
                {
                    landing = touchdown.State;
                }

                foreach (FlightEvent e in events)
                {
                    if (e.Kind == FlightEventKinds.Apex && apex is null)
                    {
                        apex = e.State;
                    }
                    else if (e.Kind == FlightEventKinds.PlaneCrossing)
                    {
                        NamedPlane plane = scenario.Planes[e.PlaneIndex];
                        crossings.Add(new Crossing(plane.Name, e.State, plane.Bounds?.Contains(e.Position, plane.Point)));
                    }
                }

                points?.Add(new StepPoint(stepper.State, stepper.Derivative));
            }

            // The last step point may lie past the landing: it stays for the interpolant, but the flight ends at the landing.
            FlightState end = landing ?? stepper.State;
            return new FlightResult(scenario, landing, apex, crossings, checked((int)stepper.StepCount), stepper.DerivativeEvaluations, end, points);
        }
    }
}
