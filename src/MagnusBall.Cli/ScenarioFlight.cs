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
        IReadOnlyList<StepPoint>? Points,
        IReadOnlyList<FlightEvent>? Contacts = null)
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

    /// <summary>What a flight must keep for the output: nothing, every step (CSV rows), or the steps that hold given sample counts.</summary>
    internal sealed record Recording(bool AllSteps, IReadOnlyList<int> SampleCounts)
    {
        /// <summary>Keep nothing but the summary.</summary>
        public static Recording None { get; } = new Recording(false, Array.Empty<int>());
    }

    /// <summary>
    /// The work one scenario file may cost, in model evaluations (calls of <see cref="FlightModel.Derivative"/>), shared
    /// by all the scenarios of a file and by a second flight for the samples, so no file can run unbounded. A step is
    /// charged before it is taken, at the integrator's evaluations per step times the substeps a substepping integrator
    /// (stable-rk4) will take (as <see cref="StableIntegrator.SubstepCount"/> judges it at the start of the step: an upper
    /// estimate), and each flight's start costs one.
    /// </summary>
    internal sealed class WorkBudget
    {
        public WorkBudget(long evaluations) => Remaining = evaluations;

        public long Limit => Total + Remaining;

        public long Remaining { get; private set; }

        public long Total { get; private set; }

        public bool TrySpend(long evaluations)
        {
            if (evaluations > Remaining)
            {
                return false;
            }

            Remaining -= evaluations;
            Total += evaluations;
            return true;
        }
    }

    /// <summary>
    /// Flies a <see cref="Scenario"/> with its integrator at its fixed step until it lands (first crossing of
    /// the ground plane against its normal) or reaches maxTime, locating the apex and every plane crossing
    /// between steps on the cubic Hermite interpolant.
    /// </summary>
    internal static class ScenarioFlight
    {
        /// <summary>
        /// Most step points kept in memory while a flight runs for its samples (--samples, --svg): 65,536 (10 MB). A
        /// longer flight is flown a second time keeping only the steps that hold a sample, so memory stays bounded
        /// by the samples printed, not by the steps taken.
        /// </summary>
        public const int MaxKeptPoints = 1 << 16;

        /// <summary>Most rows --csv without --samples prints for one scenario (one per step): 1,000,000.</summary>
        public const int MaxCsvRows = 1_000_000;

        /// <summary>
        /// Most model evaluations the flights of one file may cost: 4e6 (1e6 RK4 steps, 4e6 Euler steps, 666,666
        /// Dormand-Prince steps; 2 s to 4 s on a loaded 2.1 GHz core, docs/cli.md). Work, not steps, is what takes time:
        /// a step of dp54 costs 6 evaluations and one of Euler 1.
        /// </summary>
        public const long MaxEvaluationsPerFile = 4_000_000;

        /// <summary>The budget <see cref="Program"/> gives a file: <see cref="MaxEvaluationsPerFile"/> (lowered by the fuzz test to keep it short).</summary>
        internal static long EvaluationsPerFileLimit { get; set; } = MaxEvaluationsPerFile;

        public static FlightResult Simulate(Scenario scenario, bool recordSteps) =>
            Simulate(scenario, recordSteps ? new Recording(true, Array.Empty<int>()) : Recording.None, new WorkBudget(MaxEvaluationsPerFile));

        public static FlightResult Simulate(Scenario scenario, Recording recording, WorkBudget budget)
        {
            if (recording.AllSteps)
            {
                return Fly(scenario, budget, keepAll: MaxCsvRows, keep: null, csvRows: true);
            }

            if (recording.SampleCounts.Count == 0)
            {
                return Fly(scenario, budget, keepAll: 0, keep: null, csvRows: false);
            }

            // Keep every step while there are few; past MaxKeptPoints, drop them, finish the flight, and fly it again
            // keeping only the steps that hold a sample (the same steps, so the same samples, bit for bit).
            FlightResult first = Fly(scenario, budget, keepAll: MaxKeptPoints, keep: null, csvRows: false);
            if (first.Points != null)
            {
                return first;
            }

            var times = new List<double>();
            foreach (int count in recording.SampleCounts)
            {
                times.AddRange(SampleTimes(scenario.Initial.Time, first.End.Time, count));
            }

            times.Sort();
            return Fly(scenario, budget, keepAll: 0, keep: times, csvRows: false);
        }

        /// <summary>The times of <paramref name="count"/> samples evenly spaced from <paramref name="t0"/> to <paramref name="t1"/>.</summary>
        public static IEnumerable<double> SampleTimes(double t0, double t1, int count)
        {
            for (int i = 0; i < count; i++)
            {
                yield return i == count - 1 ? t1 : t0 + (t1 - t0) * i / (count - 1);
            }
        }

        private static InputError OverBudget(Scenario scenario, WorkBudget budget, double reached) =>
            new InputError($"scenarios[{scenario.Index}].step",
                $"the file's flights need more than {budget.Limit} model evaluations ({scenario.Integrator.Name} makes " +
                $"{scenario.Integrator.DerivativeEvaluationsPerStep} per step{(scenario.Integrator is StableIntegrator ? ", times its substeps" : string.Empty)}; " +
                $"this flight reached t = {JsonFields.Format(reached)} s); at most {budget.Limit} are allowed per file so that no file runs unbounded: " +
                "use a larger step, a shorter maxTime or a cheaper integrator");

        // keepAll > 0: keep every step point up to that many (beyond: csvRows fails, else the points are dropped).
        // keep != null: keep only the steps [a, b) that contain one of these sorted times (both ends).
        private static FlightResult Fly(Scenario scenario, WorkBudget budget, int keepAll, List<double>? keep, bool csvRows)
        {
            FlightModel model = scenario.Model;
            double endTime = scenario.Initial.Time + scenario.MaxTime;
            string stepPath = $"scenarios[{scenario.Index}].step";

            // The library's one flight core: each step's end derivative is the next step's start, the cubic Hermite
            // of the step costs nothing more, and the events are located on it to 1e-12 s.
            Plane? ground = scenario.Ground is NamedPlane g ? new Plane(g.Point, g.Normal) : null;
            var planes = scenario.Planes.Select(p => new Plane(p.Point, p.Normal)).ToArray();
            // Shapes (issue 40): a touch is a Contact event, answered by the shape; the flight goes on.
            var shapes = scenario.Shapes is { Count: > 0 } list ? list.ToArray() : null;
            var stepper = new FlightStepper(model, scenario.Integrator, new FlightEventSet(model.Up, ground, planes), null, shapes);
            var contacts = new List<FlightEvent>();
            var stepContacts = new List<StepPoint>(); // this step's contacts: the states before and after each
            if (!budget.TrySpend(1))
            {
                throw OverBudget(scenario, budget, scenario.Initial.Time);
            }

            stepper.Reset(scenario.Initial); // one evaluation, at the start state
            var stable = scenario.Integrator as StableIntegrator;
            StableIntegrator? bound = StabilityCheck.For(scenario.Integrator);

            List<StepPoint>? points = keepAll > 0 || keep != null ? new List<StepPoint>() : null;
            if (keepAll > 0)
            {
                points!.Add(new StepPoint(stepper.State, stepper.Derivative));
            }

            int nextKeep = 0;
            var crossings = new List<Crossing>();
            FlightState? apex = null;
            FlightState? landing = null;

            // Bounded: each pass advances the clock by a step (the last one trimmed to maxTime by the library's one
            // end-time rule) or ends the run, and every step is paid for from the file's work budget.
            while (true)
            {
                double before = stepper.State.Time;
                var start = new StepPoint(stepper.State, stepper.Derivative);
                double h = FlightStepper.StepToward(before, endTime, scenario.Step, out bool last);

                // A step beyond the method's stability bound for the flight's drag is refused before it is taken: its
                // growth may stay finite for a while, and a "landing" it reached would be printed as a result.
                StabilityCheck.Require(bound, scenario.Integrator, model, stepper.State, h, stepPath);

                // The work cap: a step costs the integrator's evaluations per step, a substepping integrator's step that
                // times the substeps it will take (judged at the start of the step, as the integrator judges it).
                long substeps = stable is null || !(h > 0) ? 1 : stable.SubstepCount(model, stepper.State, h);
                if (!budget.TrySpend(substeps * scenario.Integrator.DerivativeEvaluationsPerStep))
                {
                    throw OverBudget(scenario, budget, before);
                }

                StepOutcome outcome;
                try
                {
                    outcome = stepper.TryStep(h, FlightEventKinds.Landing);
                }
                catch (ArgumentException)
                {
                    // A safety net: an integrator that throws on a non-finite intermediate state has diverged.
                    outcome = StepOutcome.Diverged;
                }

                if (outcome == StepOutcome.Diverged)
                {
                    // The core refused the step (the state is kept), so the error can name the step.
                    throw new InputError(stepPath,
                        $"the flight diverged (the state would not be finite after t = {JsonFields.Format(before)} s with {scenario.Integrator.Name}); use a smaller step or stable-rk4");
                }

                if (outcome == StepOutcome.TimeCannotAdvance)
                {
                    throw new InputError(
                        $"scenarios[{scenario.Index}].initial.time",
                        $"a step of {JsonFields.Format(h)} s does not advance the clock at t = {JsonFields.Format(before)} s (the time is too large for double precision); start the flight at a smaller time");
                }

                // The core stops at the landing: the events it reports are those that happen (nothing after the landing).
                stepContacts.Clear();
                foreach (FlightEvent e in stepper.Events)
                {
                    if (e.Kind == FlightEventKinds.Contact)
                    {
                        // The velocity jumps there: the samples' Hermite pieces end before it and start after it.
                        contacts.Add(e);
                        stepContacts.Add(new StepPoint(e.State, model.Derivative(e.State)));
                        stepContacts.Add(new StepPoint(e.After, model.Derivative(e.After)));
                    }
                    else if (e.Kind == FlightEventKinds.Landing)
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

                var end = new StepPoint(stepper.State, stepper.Derivative);
                if (keep != null)
                {
                    // The step [before, end) holds a sample: keep both ends (the start may already be the last kept).
                    bool holds = false;
                    while (nextKeep < keep.Count && keep[nextKeep] < end.State.Time)
                    {
                        holds |= keep[nextKeep] >= before;
                        nextKeep++;
                    }

                    if (holds)
                    {
                        if (points!.Count == 0 || points[^1].State.Time != before)
                        {
                            points.Add(start);
                        }

                        points.AddRange(stepContacts);
                        points.Add(end);
                    }
                }
                else if (points != null)
                {
                    if (points.Count >= keepAll)
                    {
                        if (csvRows)
                        {
                            throw new InputError(stepPath,
                                $"--csv without --samples prints one row per step, and this flight takes more than {MaxCsvRows} steps; use --samples N");
                        }

                        points = null; // too many to keep: the caller flies again for the samples only
                    }
                    else
                    {
                        points.AddRange(stepContacts);
                        points.Add(end);
                    }
                }

                if (stepper.IsStopped || last)
                {
                    break;
                }
            }

            if (keep != null && points!.Count == 0)
            {
                points.Add(new StepPoint(stepper.State, stepper.Derivative));
            }

            FlightState final = stepper.State;
            return new FlightResult(scenario, landing, apex, crossings, checked((int)stepper.StepCount), stepper.DerivativeEvaluations, final, points, contacts);
        }
    }
}
