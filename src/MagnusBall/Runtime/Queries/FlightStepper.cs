using System;
using MagnusBall.Integration;

namespace MagnusBall.Queries
{
    /// <summary>
    /// Steps one ball's flight and reports the events inside each step: the one stepping loop that the
    /// trajectory predictor, the aim solvers, a fixed-step game driver and the CLI all share. Mutable (it
    /// holds the ball's current state); allocates only when constructed.
    /// </summary>
    /// <remarks>
    /// <para>Each step reuses the derivative at the end of the previous step as its start derivative, so a
    /// step costs exactly <see cref="IIntegrator.DerivativeEvaluationsPerStep"/> evaluations, and the cubic
    /// Hermite dense output (<see cref="LastSegment"/>) and every event located on it cost none.</para>
    /// <para>Not thread-safe: use one stepper per ball and thread. The model, integrator and event set it
    /// holds are immutable and may be shared.</para>
    /// </remarks>
    public sealed class FlightStepper
    {
        private readonly FlightEvent[] _events;
        private FlightState _state;
        private StateDerivative _derivative;
        private HermiteSegment _segment;
        private int _eventCount;
        private bool _started;
        private bool _startsFlight; // the next step is the first since Reset/SetState: a start on a plane heading through it counts

        /// <summary>Creates a stepper; call <see cref="Reset"/> to give it a state.</summary>
        /// <param name="model">The flight model.</param>
        /// <param name="integrator">The integration method.</param>
        /// <param name="events">What to look for in each step, or null for no events.</param>
        /// <exception cref="ArgumentNullException">model or integrator is null.</exception>
        public FlightStepper(FlightModel model, IIntegrator integrator, FlightEventSet? events = null)
        {
            Model = Require.NotNull(model, nameof(model));
            Integrator = Require.NotNull(integrator, nameof(integrator));
            EventSet = events;
            _events = new FlightEvent[events?.MaximumEventsPerStep ?? 0];
        }

        /// <summary>The flight model.</summary>
        public FlightModel Model { get; }

        /// <summary>The integration method.</summary>
        public IIntegrator Integrator { get; }

        /// <summary>The events looked for in each step, or null.</summary>
        public FlightEventSet? EventSet { get; }

        /// <summary>The current state (the end of the last step).</summary>
        public FlightState State => _state;

        /// <summary>The derivative at the current state (the next step's start derivative).</summary>
        public StateDerivative Derivative => _derivative;

        /// <summary>The dense output of the last step (default before the first step).</summary>
        public HermiteSegment LastSegment => _segment;

        /// <summary>The events inside the last step, in time order.</summary>
        public ReadOnlySpan<FlightEvent> Events => new ReadOnlySpan<FlightEvent>(_events, 0, _eventCount);

        /// <summary>Steps taken since the last <see cref="Reset"/>.</summary>
        public long StepCount { get; private set; }

        /// <summary>Derivative evaluations since the last <see cref="Reset"/> (including the one at the start state).</summary>
        public long DerivativeEvaluations { get; private set; }

        /// <summary>
        /// Starts a new flight from <paramref name="state"/>: sets the state, evaluates its derivative, zeroes the
        /// counters. A ball placed exactly on the ground or a watched plane and heading through it crosses it at
        /// the start of the next step (a ball launched from the ground into it lands at once).
        /// </summary>
        /// <param name="state">The start state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite.</exception>
        public void Reset(in FlightState state)
        {
            CheckState(state);
            StepCount = 0;
            DerivativeEvaluations = 0;
            SetStateUnchecked(state);
        }

        /// <summary>
        /// Replaces the current state mid-flight (after a bounce, a hit, a teleport) without zeroing the
        /// counters. Evaluates the new state's derivative (one evaluation) and clears the last step's events. As
        /// after <see cref="Reset"/>, a state exactly on a plane and heading through it crosses it at the start of
        /// the next step; a ball leaving the plane (after a bounce) does not.
        /// </summary>
        /// <param name="state">The new state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite.</exception>
        public void SetState(in FlightState state)
        {
            CheckState(state);
            SetStateUnchecked(state);
        }

        /// <summary>
        /// Advances the flight by <paramref name="step"/> seconds and locates the events inside the step
        /// (see <see cref="Events"/>). Allocates nothing.
        /// </summary>
        /// <remarks>
        /// A step far beyond the integrator's stability limit for this ball and speed (explicit methods diverge
        /// beyond about step = 2 / (k C_D s), 2.45 / (k C_D s) for RK4, k = <see cref="FlightModel.AerodynamicFactor"/>) makes the state
        /// overflow. <see cref="Step"/> still takes it, reports no events, and leaves the non-finite state in
        /// <see cref="State"/> for the caller to detect (<see cref="FlightState.IsFinite"/>); the next step then
        /// throws. <see cref="TryStep"/> refuses such a step instead and keeps the last finite state.
        /// </remarks>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <returns>The number of events inside the step.</returns>
        /// <exception cref="InvalidOperationException">No state was given yet (<see cref="Reset"/>).</exception>
        /// <exception cref="ArgumentException">The step is not finite and positive, or the current state is not finite (a previous step diverged).</exception>
        public int Step(double step)
        {
            Advance(step, acceptDivergence: true);
            return _eventCount;
        }

        /// <summary>
        /// Advances the flight by <paramref name="step"/> seconds and locates the events inside the step,
        /// unless the step diverges (the new state would have a non-finite component, as when the step is
        /// far beyond the integrator's stability limit): then it returns false and leaves the state unchanged.
        /// Allocates nothing.
        /// </summary>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <returns>True when the step was taken (<see cref="Events"/> holds its events).</returns>
        /// <exception cref="InvalidOperationException">No state was given yet (<see cref="Reset"/>).</exception>
        /// <exception cref="ArgumentOutOfRangeException">The step is not finite and positive.</exception>
        public bool TryStep(double step) => Advance(step, acceptDivergence: false);

        private bool Advance(double step, bool acceptDivergence)
        {
            if (!_started)
            {
                throw new InvalidOperationException("Call Reset(state) before Step.");
            }

            Require.Step(step, nameof(step));
            FlightState next = Integrator.Step(Model, _state, _derivative, step);
            StateDerivative nextDerivative = Model.Derivative(next);
            DerivativeEvaluations += Integrator.DerivativeEvaluationsPerStep;
            if (!next.IsFinite || !(next.Time > _state.Time) || !IsFinite(nextDerivative))
            {
                _eventCount = 0;
                if (acceptDivergence)
                {
                    StepCount++;
                    _segment = default;
                    _state = next;
                    _derivative = nextDerivative;
                }

                return false;
            }

            StepCount++;
            _segment = new HermiteSegment(_state, _derivative, next, nextDerivative);
            _state = next;
            _derivative = nextDerivative;
            _eventCount = EventSet == null ? 0 : EventSet.Scan(_segment, _events, _startsFlight);
            _startsFlight = false;
            return true;
        }

        private static bool IsFinite(in StateDerivative d) => d.Velocity.IsFinite && d.Acceleration.IsFinite && d.AngularAcceleration.IsFinite;

        /// <summary>The first event of one of the <paramref name="kinds"/> inside the last step.</summary>
        /// <param name="kinds">The kinds to look for.</param>
        /// <param name="found">The event; default when none.</param>
        /// <returns>True when one was found.</returns>
        public bool TryGetEvent(FlightEventKinds kinds, out FlightEvent found)
        {
            for (int i = 0; i < _eventCount; i++)
            {
                if ((_events[i].Kind & kinds) != 0)
                {
                    found = _events[i];
                    return true;
                }
            }

            found = default;
            return false;
        }

        /// <summary>
        /// The events inside the last step that happen when the flight ends at the first event of the
        /// <paramref name="stopAt"/> kinds: those up to it and any at the same instant, in time order (see
        /// <see cref="FlightEventSet.CountUntil"/>). For a flight that ends at the landing: the apex and the plane
        /// crossings before the landing count, nothing after it. Allocates nothing.
        /// </summary>
        /// <param name="stopAt">The kinds that end the flight (None: every event of the step).</param>
        /// <param name="stopped">True when an event of those kinds happened in the last step.</param>
        /// <param name="stopEvent">The first such event; default when none.</param>
        /// <returns>The events that happen, in time order (the stop event among them).</returns>
        public ReadOnlySpan<FlightEvent> EventsUntil(FlightEventKinds stopAt, out bool stopped, out FlightEvent stopEvent)
        {
            ReadOnlySpan<FlightEvent> events = Events;
            int count = FlightEventSet.CountUntil(events, stopAt, out int stopIndex);
            stopped = stopIndex >= 0;
            stopEvent = stopped ? SpanView.Of(events)[stopIndex] : default;
            return events.Slice(0, count);
        }

        private void SetStateUnchecked(in FlightState state)
        {
            _state = state;
            _derivative = Model.Derivative(state);
            DerivativeEvaluations++;
            _segment = default;
            _eventCount = 0;
            _started = true;
            _startsFlight = true;
        }

        private static void CheckState(in FlightState state)
        {
            if (!state.IsFinite)
            {
                throw new ArgumentException(
                    $"state must have finite position, velocity, angular velocity and time; got {state}.", nameof(state));
            }
        }
    }
}
