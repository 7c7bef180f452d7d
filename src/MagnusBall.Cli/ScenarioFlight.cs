using System;
using System.Collections.Generic;
using System.Linq;
using MagnusBall.Flight;
using MagnusBall.Integration;

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
    internal static class ScenarioFlight
    {
        public static FlightResult Simulate(Scenario scenario, bool recordSteps)
        {
            FlightModel model = scenario.Model;
            double endTime = scenario.Initial.Time + scenario.MaxTime;

            // The library's one flight core: each step's end derivative is the next step's start, the cubic Hermite
            // of the step costs nothing more, and the events are located on it to 1e-12 s.
            Plane? ground = scenario.Ground is NamedPlane g ? new Plane(g.Point, g.Normal) : null;
            var planes = scenario.Planes.Select(p => new Plane(p.Point, p.Normal)).ToArray();
            var stepper = new FlightStepper(model, scenario.Integrator, new FlightEventSet(model.Up, ground, planes));
            stepper.Reset(scenario.Initial);

            var points = recordSteps ? new List<StepPoint> { new StepPoint(stepper.State, stepper.Derivative) } : null;
            var crossings = new List<Crossing>();
            FlightState? apex = null;
            FlightState? landing = null;

            // Bounded: each pass advances the clock by a step (the last one trimmed to maxTime by the library's one
            // end-time rule) or ends the run.
            while (true)
            {
                double before = stepper.State.Time;
                double h = FlightStepper.StepToward(before, endTime, scenario.Step, out bool last);
                StepOutcome outcome = stepper.TryStep(h, FlightEventKinds.Landing);
                if (outcome == StepOutcome.Diverged)
                {
                    // The core refused the step (the state is kept), so the error can name the step.
                    throw new InputError(
                        $"scenarios[{scenario.Index}].step",
                        $"the flight diverged (the state would not be finite after t = {JsonFields.Format(before)} s with {scenario.Integrator.Name}); use a smaller step or stable-rk4");
                }

                if (outcome == StepOutcome.TimeCannotAdvance)
                {
                    throw new InputError(
                        $"scenarios[{scenario.Index}].initial.time",
                        $"a step of {JsonFields.Format(h)} s does not advance the clock at t = {JsonFields.Format(before)} s (the time is too large for double precision); start the flight at a smaller time");
                }

                // The core stops at the landing: the events it reports are those that happen (nothing after the landing).
                foreach (FlightEvent e in stepper.Events)
                {
                    if (e.Kind == FlightEventKinds.Landing)
                    {
                        landing = e.State;
                    }
                    else if (e.Kind == FlightEventKinds.Apex && apex is null)
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
                if (stepper.IsStopped || last)
                {
                    break;
                }
            }

            FlightState end = stepper.State;
            return new FlightResult(scenario, landing, apex, crossings, checked((int)stepper.StepCount), stepper.DerivativeEvaluations, end, points);
        }
    }
}
