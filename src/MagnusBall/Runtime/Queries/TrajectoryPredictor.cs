using System;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;

namespace MagnusBall.Queries
{
    /// <summary>
    /// The outcome of one <see cref="TrajectoryPredictor"/> run: where the flight ended and why, how many
    /// samples and events were written to the caller's buffers, and what it cost.
    /// </summary>
    public readonly struct Prediction
    {
        /// <summary>Creates a prediction result.</summary>
        /// <param name="endState">The last state: the stop event's state, or the state at the time limit.</param>
        /// <param name="stopped">True when an event of the requested kinds ended the run.</param>
        /// <param name="stopEvent">The event that ended the run (default when <paramref name="stopped"/> is false).</param>
        /// <param name="sampleCount">Samples written.</param>
        /// <param name="samplesTruncated">True when the sample buffer filled before the end.</param>
        /// <param name="eventCount">Events written.</param>
        /// <param name="eventsTruncated">True when the event buffer filled before the end.</param>
        /// <param name="steps">Integrator steps taken.</param>
        /// <param name="derivativeEvaluations">Derivative evaluations made (including the start state's).</param>
        /// <param name="diverged">True when the run ended because a step diverged (see <see cref="FlightStepper.TryStep"/>).</param>
        /// <param name="timeCannotAdvance">True when the run ended because the clock could not advance (see <see cref="StepOutcome.TimeCannotAdvance"/>).</param>
        /// <param name="workLimitReached">True when the run ended at <see cref="TrajectoryPredictor.MaxEvaluationsPerPrediction"/>.</param>
        internal Prediction(
            in FlightState endState, bool stopped, in FlightEvent stopEvent, int sampleCount, bool samplesTruncated,
            int eventCount, bool eventsTruncated, long steps, long derivativeEvaluations, bool diverged = false, bool timeCannotAdvance = false,
            bool workLimitReached = false)
        {
            WorkLimitReached = workLimitReached;
            Diverged = diverged;
            TimeCannotAdvance = timeCannotAdvance;
            EndState = endState;
            Stopped = stopped;
            StopEvent = stopEvent;
            SampleCount = sampleCount;
            SamplesTruncated = samplesTruncated;
            EventCount = eventCount;
            EventsTruncated = eventsTruncated;
            Steps = steps;
            DerivativeEvaluations = derivativeEvaluations;
        }

        /// <summary>The last state: the stop event's interpolated state, or the state at the time limit.</summary>
        public readonly FlightState EndState;

        /// <summary>True when an event of the requested kinds ended the run; false when the time limit (or a divergence) did.</summary>
        public readonly bool Stopped;

        /// <summary>The event that ended the run (default when <see cref="Stopped"/> is false).</summary>
        public readonly FlightEvent StopEvent;

        /// <summary>How many samples were written to the caller's buffer.</summary>
        public readonly int SampleCount;

        /// <summary>True when the sample buffer filled up before the run ended (the run itself went on).</summary>
        public readonly bool SamplesTruncated;

        /// <summary>How many events were written to the caller's event buffer.</summary>
        public readonly int EventCount;

        /// <summary>True when the event buffer filled up before the run ended.</summary>
        public readonly bool EventsTruncated;

        /// <summary>Integrator steps taken.</summary>
        public readonly long Steps;

        /// <summary>Derivative evaluations made, including the one at the start state: the honest unit of cost.</summary>
        public readonly long DerivativeEvaluations;

        /// <summary>
        /// True when the run ended early because a step diverged (the step is far beyond the integrator's
        /// stability limit for this ball and speed); <see cref="EndState"/> is then the last finite state.
        /// </summary>
        public readonly bool Diverged;

        /// <summary>
        /// True when the run ended early because the start time is so large that a step no longer advances the clock
        /// (the state is finite; start the flight at a smaller time). <see cref="EndState"/> is the last state.
        /// </summary>
        public readonly bool TimeCannotAdvance;

        /// <summary>
        /// True when the run ended early, before its time limit and without a stop event, because it had made
        /// <see cref="TrajectoryPredictor.MaxEvaluationsPerPrediction"/> model evaluations plus steps plus pieces of the shapes' touch
        /// searches (a tiny step or a huge maxDuration, or a ball caught between shapes; the bounded work of one call). <see cref="EndState"/> is the state reached, a true state of the flight.
        /// </summary>
        public readonly bool WorkLimitReached;
    }

    /// <summary>
    /// Predicts a flight ahead of time: from a state, steps at a fixed step until an event of the requested
    /// kinds (by default the landing) or a time limit, writing sampled points into caller-provided buffers
    /// (for a line renderer, an AI or a replay). Allocates nothing per prediction.
    /// </summary>
    /// <remarks>
    /// Built on <see cref="FlightStepper"/>, so it locates events exactly as a running simulation does and
    /// a prediction made with the same model, integrator and step matches the flight step for step. Holds
    /// a stepper, so one predictor is not thread-safe; create one per thread.
    /// </remarks>
    public sealed class TrajectoryPredictor
    {
        /// <summary>
        /// The work cap of one prediction: after the step that brings its model evaluations plus its steps plus the pieces of path
        /// its shapes' touch searches looked at to this many (1,000,000; a step's own work, its dense output and event scan, costs
        /// about one evaluation, and so does a piece of a search, which tests one point against one shape: 200,000 RK4 steps,
        /// 14 minutes of flight at 1/240 s, or 500,000 Euler steps; measured up to 4 s on a loaded core with the golf laws,
        /// docs/robustness.md), the run ends with
        /// <see cref="Prediction.WorkLimitReached"/>. It bounds a huge maxDuration against a small step, and a step that
        /// <see cref="StableIntegrator"/> splits into thousands of substeps.
        /// </summary>
        internal const long MaxEvaluationsPerPrediction = 1_000_000;

        private readonly FlightStepper _stepper;

        /// <summary>Creates a predictor.</summary>
        /// <param name="model">The flight model.</param>
        /// <param name="integrator">The integration method.</param>
        /// <param name="step">The fixed step, s; finite and &gt; 0.</param>
        /// <param name="events">The events to locate; null for <see cref="FlightEventSet.ForModel"/> (landing on the ground through the origin, and the apex).</param>
        /// <param name="shapes">Shapes the ball meets on the way (a net, posts, a wall: <c>MagnusBall.Contact.Shapes</c>, docs/contacts.md):
        /// each touch is a <see cref="FlightEventKinds.Contact"/> event and the prediction goes on from the ball's response; null for none.</param>
        /// <exception cref="ArgumentNullException">model or integrator is null.</exception>
        /// <exception cref="ArgumentOutOfRangeException">step is not finite and positive.</exception>
        /// <exception cref="ArgumentException">shapes holds a null entry.</exception>
        public TrajectoryPredictor(FlightModel model, IIntegrator integrator, double step, FlightEventSet? events = null, ContactShape[]? shapes = null)
        {
            Require.NotNull(model, nameof(model));
            Require.NotNull(integrator, nameof(integrator));
            Step = Require.Step(step, nameof(step));
            _stepper = new FlightStepper(model, integrator, events ?? FlightEventSet.ForModel(model), contact: null, shapes);
        }

        /// <summary>The fixed step, s.</summary>
        public double Step { get; }

        /// <summary>The flight model.</summary>
        public FlightModel Model => _stepper.Model;

        /// <summary>The integration method.</summary>
        public IIntegrator Integrator => _stepper.Integrator;

        /// <summary>The events located in each step.</summary>
        public FlightEventSet Events => _stepper.EventSet!;

        /// <summary>
        /// Predicts positions only: writes the start position, every step's end position and the end position
        /// (stop event or time limit) into <paramref name="positions"/>.
        /// </summary>
        /// <param name="start">The start state; every component finite.</param>
        /// <param name="maxDuration">How long to fly at most, s; finite and &gt; 0.</param>
        /// <param name="positions">Where to write the sampled positions (may be empty).</param>
        /// <param name="stopAt">Which event kinds end the run (default: the landing; None flies to the time limit).</param>
        /// <returns>Where it ended, why (a stop event, the time limit, a divergence, or the work cap
        /// <see cref="MaxEvaluationsPerPrediction"/>), and how many samples were written.</returns>
        /// <exception cref="ArgumentException">The state is not finite or maxDuration is out of range.</exception>
        public Prediction Predict(in FlightState start, double maxDuration, Span<Vector3d> positions, FlightEventKinds stopAt = FlightEventKinds.Landing) =>
            Run(start, maxDuration, positions, Span<FlightState>.Empty, Span<FlightEvent>.Empty, stopAt);

        /// <summary>
        /// Predicts full states: writes the start state, every step's end state and the end state into
        /// <paramref name="samples"/>, and every located event up to and including the stop event (and any at the same instant), in time
        /// order, into <paramref name="events"/>.
        /// </summary>
        /// <param name="start">The start state; every component finite.</param>
        /// <param name="maxDuration">How long to fly at most, s; finite and &gt; 0.</param>
        /// <param name="samples">Where to write the sampled states (may be empty).</param>
        /// <param name="events">Where to write the events (may be empty).</param>
        /// <param name="stopAt">Which event kinds end the run (default: the landing; None flies to the time limit).</param>
        /// <returns>Where it ended, why, and how many samples and events were written.</returns>
        /// <exception cref="ArgumentException">The state is not finite or maxDuration is out of range.</exception>
        public Prediction Predict(
            in FlightState start, double maxDuration, Span<FlightState> samples, Span<FlightEvent> events, FlightEventKinds stopAt = FlightEventKinds.Landing) =>
            Run(start, maxDuration, Span<Vector3d>.Empty, samples, events, stopAt);

        private Prediction Run(
            in FlightState start, double maxDuration, Span<Vector3d> positions, Span<FlightState> states, Span<FlightEvent> events, FlightEventKinds stopAt)
        {
            Require.Positive(maxDuration, nameof(maxDuration));
            FlightStepper stepper = _stepper;
            stepper.Reset(start);

            int sampleCount = 0, eventCount = 0;
            bool samplesTruncated = false, eventsTruncated = false;
            Write(start, positions, states, ref sampleCount, ref samplesTruncated);

            double endTime = start.Time + maxDuration;
            // Bounded: each pass advances the clock by a step (or refuses and returns), so at most
            // maxDuration / Step + 1 passes, and the work cap ends the run after MaxEvaluationsPerPrediction evaluations.
            while (true)
            {
                if (stepper.Work >= MaxEvaluationsPerPrediction)
                {
                    return new Prediction(
                        stepper.State, false, default, sampleCount, samplesTruncated, eventCount, eventsTruncated,
                        stepper.StepCount, stepper.DerivativeEvaluations, workLimitReached: true);
                }

                double h = FlightStepper.StepTowardUnchecked(stepper.CurrentTime, endTime, Step, out bool last);
                // h is 0 when maxDuration is below the time's resolution (start.Time + maxDuration == start.Time): the clock
                // cannot advance, which the stepper reports for any step that does not move it.
                StepOutcome outcome = h > 0 ? stepper.TryStep(h, stopAt) : StepOutcome.TimeCannotAdvance;
                if (outcome == StepOutcome.Diverged || outcome == StepOutcome.TimeCannotAdvance)
                {
                    return new Prediction(
                        stepper.State, false, default, sampleCount, samplesTruncated, eventCount, eventsTruncated,
                        stepper.StepCount, stepper.DerivativeEvaluations, diverged: outcome == StepOutcome.Diverged,
                        timeCannotAdvance: outcome == StepOutcome.TimeCannotAdvance);
                }

                if (stepper.EventCount != 0)
                {
                    // (Tested first: most steps hold no event, and building the two spans is work for nothing there; under Mono
                    // about 1 us of a 213 us predicted full-model shot.)
                    Span<FlightEvent> found = SpanView.Of(stepper.Events); // not the read-only indexer: Mono 6.8 lacks it
                    for (int i = 0; i < found.Length; i++)
                    {
                        if (eventCount < events.Length)
                        {
                            events[eventCount++] = found[i];
                        }
                        else if (events.Length > 0)
                        {
                            eventsTruncated = true;
                        }
                    }
                }

                Write(stepper.CurrentState, positions, states, ref sampleCount, ref samplesTruncated);
                if (stepper.IsStopped || last)
                {
                    return new Prediction(
                        stepper.State, stepper.IsStopped, stepper.StopEvent, sampleCount, samplesTruncated, eventCount, eventsTruncated,
                        stepper.StepCount, stepper.DerivativeEvaluations);
                }
            }
        }

        private static void Write(in FlightState state, Span<Vector3d> positions, Span<FlightState> states, ref int count, ref bool truncated)
        {
            int capacity = Math.Max(positions.Length, states.Length);
            if (count >= capacity)
            {
                truncated |= capacity > 0;
                return;
            }

            if (positions.Length > 0)
            {
                positions[count] = state.Position;
            }
            else
            {
                states[count] = state;
            }

            count++;
        }
    }
}
