using System;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Queries;

namespace MagnusBall.Stepping
{
    /// <summary>
    /// Turns a game engine's variable frame time into fixed integration steps, so that a shot flies the same
    /// path at 30, 60 or 144 frames per second and through hitches: the MonoBehaviour-style adapter. Call
    /// <see cref="Advance(double, Span{FrameEvent})"/> once per frame with the frame's delta time, then draw
    /// the ball at <see cref="RenderState"/>.
    /// </summary>
    /// <remarks>
    /// <para>The pattern is Fiedler's "Fix Your Timestep!" (Gaffer On Games, 2004): frame time goes into an
    /// accumulator; whole fixed steps are taken out of it; what is left (less than one step) says how far
    /// the renderer is between the last two fixed states, alpha = accumulator / step. A frame longer than
    /// <see cref="MaxFrameDeltaSeconds"/> (a hitch: loading, a breakpoint, the window dragged) is clamped, and
    /// at most <see cref="MaxStepsPerAdvance"/> steps are taken per call, so one slow frame cannot trigger
    /// ever more steps (the "spiral of death"). Time that is clamped or capped away is dropped: the ball
    /// falls behind the wall clock but flies exactly the same path, because the path depends only on the
    /// sequence of fixed steps, never on how frame time was sliced.</para>
    /// <para>The seed thesis (Agrawal 2023, section 3.1.3) stepped its ODE once per frame with Unity's
    /// <c>Time.deltaTime</c>, so its landing point depended on the frame rate; docs/unity.md puts numbers
    /// on that difference.</para>
    /// <para>Events (landing, bounces, apex, plane crossings) are located inside the step where they happen
    /// by <see cref="FlightEventSet.Scan"/> on the step's cubic Hermite (<see cref="HermiteSegment"/>; no extra
    /// derivative evaluation) and written to a caller-provided buffer. Without a bounce model the flight ends
    /// at the first landing (the last step is cut there). With one, each fixed step is a
    /// <see cref="BouncingFlight.Step"/>: contacts are located on the step's Hermite, the bounce is applied at
    /// the contact time and the step finished from there, so the fixed time grid is kept; the ball rolls once
    /// a bounce is too weak and the flight ends when it stops. Nothing here allocates after construction.</para>
    /// <para>A driver owns its state and is not thread-safe; the model, integrator, event set and bounce
    /// model it uses are immutable and may be shared by any number of drivers on any threads.</para>
    /// </remarks>
    public sealed class FixedStepDriver
    {
        /// <summary>The default frame-time clamp, 0.25 s (Fiedler 2004).</summary>
        public const double DefaultMaxFrameDeltaSeconds = 0.25;

        private readonly FlightEventSet? _eventSet;
        private readonly FlightEvent[] _scratch;
        private readonly FlightStepper? _stepper;
        private readonly IBounceModel? _bounce;
        private readonly BouncingFlight? _flight;
        private readonly BounceEvent[] _bounceScratch;

        private FlightState _state;
        private StateDerivative _derivative;
        private HermiteSegment _latest;
        private HermiteSegment _older;
        private int _segmentCount;
        private double _accumulator;
        private bool _finished;
        private long _totalSteps;

        /// <summary>
        /// Creates a driver for one ball with the safe default integrator, <see cref="StableIntegrator.RungeKutta4"/>:
        /// RK4, substepped where a light, fast ball would make the fixed step unstable (docs/integrators.md).
        /// </summary>
        /// <param name="model">The flight model (shared, immutable).</param>
        /// <param name="fixedStep">The fixed step, s; finite and &gt; 0 (for example 1/240).</param>
        /// <param name="start">The launch state; every component finite.</param>
        /// <param name="events">What to look for in each step (see the full constructor); null for the ground and the apex.</param>
        /// <param name="bounce">The bounce model, or null: the flight ends at the first landing.</param>
        /// <exception cref="ArgumentNullException">model is null.</exception>
        /// <exception cref="ArgumentException">A number is out of its range (the message names it).</exception>
        public FixedStepDriver(FlightModel model, double fixedStep, in FlightState start, FlightEventSet? events = null, IBounceModel? bounce = null)
            : this(model, StableIntegrator.RungeKutta4, fixedStep, start, events, bounce)
        {
        }

        /// <summary>
        /// Creates a driver for one ball.
        /// </summary>
        /// <param name="model">The flight model (shared, immutable).</param>
        /// <param name="integrator">
        /// The integrator (shared, stateless). A plain explicit method can blow up when the fixed step is long
        /// against the drag time scale of a light, fast ball; <see cref="StableIntegrator.RungeKutta4"/> (the
        /// default of the shorter constructor) cannot.
        /// </param>
        /// <param name="fixedStep">The fixed step, s; finite and &gt; 0 (for example 1/240).</param>
        /// <param name="start">The launch state; every component finite.</param>
        /// <param name="events">
        /// What to look for in each step: the ground (landing or bounce), the apex and any planes. Null (the
        /// default) means <see cref="FlightEventSet.ForModel"/>: the ground through the origin normal to the
        /// model's up, and the apex; or no events at all when the model has no gravity.
        /// </param>
        /// <param name="bounce">
        /// The bounce model, or null (the default): the flight ends at the first landing. With one, the ball
        /// bounces off the court whose ball-centre plane is the event set's ground (the court itself lies one
        /// radius below it) through a <see cref="BouncingFlight"/>, rolls when a bounce leaves slower than
        /// <paramref name="restNormalSpeed"/>, and the flight ends when it stops.
        /// </param>
        /// <param name="maxFrameDeltaSeconds">The frame-time clamp, s; finite and &gt; 0. Default 0.25 s.</param>
        /// <param name="maxStepsPerAdvance">
        /// The most fixed steps one <see cref="Advance(double, Span{FrameEvent})"/> call takes; &gt;= 1, or 0
        /// (the default) for ceil(maxFrameDeltaSeconds / fixedStep) + 1, so that the clamp binds first.
        /// </param>
        /// <param name="restNormalSpeed">With a bounce model: bounces leaving slower than this along the normal start rolling, m/s; finite, &gt;= 0.</param>
        /// <param name="rollingResistance">With a bounce model: the rolling-resistance coefficient (see <see cref="BouncingFlight"/>); finite, &gt;= 0.</param>
        /// <exception cref="ArgumentNullException">model or integrator is null.</exception>
        /// <exception cref="ArgumentException">
        /// A number is out of its range (the message names it), or there is a bounce model but no ground.
        /// </exception>
        public FixedStepDriver(
            FlightModel model,
            IIntegrator integrator,
            double fixedStep,
            in FlightState start,
            FlightEventSet? events = null,
            IBounceModel? bounce = null,
            double maxFrameDeltaSeconds = DefaultMaxFrameDeltaSeconds,
            int maxStepsPerAdvance = 0,
            double restNormalSpeed = BouncingFlight.DefaultRestNormalSpeed,
            double rollingResistance = BouncingFlight.DefaultRollingResistance)
        {
            Model = Require.NotNull(model, nameof(model));
            Integrator = Require.NotNull(integrator, nameof(integrator));
            FixedStep = Require.Step(fixedStep, nameof(fixedStep));
            RequireFiniteState(start, nameof(start));
            MaxFrameDeltaSeconds = Require.Positive(maxFrameDeltaSeconds, nameof(maxFrameDeltaSeconds));
            Require.NonNegative(restNormalSpeed, nameof(restNormalSpeed));
            Require.NonNegative(rollingResistance, nameof(rollingResistance));
            if (maxStepsPerAdvance < 0)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(maxStepsPerAdvance), maxStepsPerAdvance, $"maxStepsPerAdvance must be >= 1, or 0 for the default; got {maxStepsPerAdvance}.");
            }

            double defaultSteps = Math.Ceiling(maxFrameDeltaSeconds / fixedStep) + 1;
            MaxStepsPerAdvance = maxStepsPerAdvance > 0 ? maxStepsPerAdvance : (int)Math.Min(defaultSteps, int.MaxValue);

            _eventSet = events ?? (model.Up.LengthSquared > 0 ? FlightEventSet.ForModel(model) : null);
            // Only the bouncing path scans steps itself; without a bounce model the FlightStepper holds the events.
            _scratch = new FlightEvent[bounce == null ? 0 : _eventSet?.MaximumEventsPerStep ?? 0];
            _bounce = bounce;
            _bounceScratch = new BounceEvent[bounce == null ? 0 : BouncingFlight.MaxSegmentsPerStep];
            if (bounce != null)
            {
                if (_eventSet?.Ground == null)
                {
                    throw new ArgumentException("bounce needs a ground plane to bounce on: give events with a ground (or a model with gravity).", nameof(bounce));
                }

                // The event set's ground is where the ball's centre touches down; the court lies one radius below.
                Plane ground = _eventSet.Ground.Value;
                var court = new Plane(ground.Point - ground.Normal * model.Ball.Radius, ground.Normal);
                _flight = new BouncingFlight(model, integrator, bounce, court, start, restNormalSpeed, rollingResistance);
            }

            else
            {
                _stepper = new FlightStepper(model, integrator, _eventSet);
            }

            Reset(start);
        }

        /// <summary>The flight model being stepped.</summary>
        public FlightModel Model { get; }

        /// <summary>The integrator.</summary>
        public IIntegrator Integrator { get; }

        /// <summary>The fixed step, s.</summary>
        public double FixedStep { get; }

        /// <summary>The frame-time clamp, s.</summary>
        public double MaxFrameDeltaSeconds { get; }

        /// <summary>The most fixed steps one Advance call takes.</summary>
        public int MaxStepsPerAdvance { get; }

        /// <summary>What the driver looks for in each step (null: nothing).</summary>
        public FlightEventSet? Events => _eventSet;

        /// <summary>The bounce model, or null when the flight ends at the first landing.</summary>
        public IBounceModel? BounceModel => _bounce;

        /// <summary>With a bounce model, the bouncing flight stepped underneath (flying, rolling or stopped); otherwise null.</summary>
        public BouncingFlight? BouncingFlight => _flight;

        /// <summary>The latest fixed state (the simulation's "now"); without a bounce model, the landing state at the end.</summary>
        public FlightState State => _flight != null ? _flight.State : _state;

        /// <summary>The start of the latest step (equal to <see cref="State"/> before the first step).</summary>
        public FlightState PreviousState => _flight != null ? _flight.PreviousState : _segmentCount > 0 ? _latest.Start : _state;

        /// <summary>Frame time not yet simulated, s: in [0, <see cref="FixedStep"/>) while flying.</summary>
        public double Accumulator => _accumulator;

        /// <summary>accumulator / step, in [0, 1]: how far the render state is through the step it is drawn in.</summary>
        public double Alpha => Math.Min(1.0, _accumulator / FixedStep);

        /// <summary>True once the flight has ended (landed without a bounce model, or stopped after bounces and rolling): Advance takes no more steps.</summary>
        public bool IsFinished => _finished;

        /// <summary>Fixed steps taken since the last reset.</summary>
        public long TotalSteps => _totalSteps;

        /// <summary>Bounces since the last reset.</summary>
        public int Bounces => _flight?.BounceCount ?? 0;

        /// <summary>
        /// The simulation time the renderer should show, s: one fixed step behind the simulation,
        /// State.Time - step + accumulator, never past <see cref="State"/> and never before the start.
        /// </summary>
        public double RenderTime => RenderState.Time;

        /// <summary>
        /// The state to draw this frame, at <see cref="RenderTime"/>: on the cubic Hermite of the step it falls
        /// in (both ends' states and derivatives, so the drawn path is C1 and keeps the curvature a linear blend
        /// of the two fixed states would cut). Allocates nothing.
        /// </summary>
        public FlightState RenderState
        {
            get
            {
                if (_flight != null)
                {
                    // BouncingFlight keeps the Hermite pieces of its last step, split at its bounces.
                    FlightState now = _flight.State;
                    return _totalSteps == 0 ? now : _flight.StateAt(Math.Min(now.Time, now.Time - FixedStep + _accumulator));
                }

                if (_segmentCount == 0)
                {
                    return _state;
                }

                double time = Math.Min(_state.Time, _state.Time - FixedStep + _accumulator);
                HermiteSegment segment = _latest;
                if (time < segment.StartTime && _segmentCount > 1)
                {
                    segment = _older;
                }

                if (time <= segment.StartTime)
                {
                    return segment.Start;
                }

                // At or past the latest segment's end: the current state (after a bounce, the state leaving the ground).
                return time >= segment.EndTime ? (segment.EndTime == _latest.EndTime ? _state : segment.End) : segment.StateAt(time);
            }
        }

        /// <summary>
        /// Restarts the flight from <paramref name="start"/>: clears the accumulator, the finished flag and the counts.
        /// </summary>
        /// <param name="start">The launch state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite (nothing is changed).</exception>
        public void Reset(in FlightState start)
        {
            RequireFiniteState(start, nameof(start));
            _state = start;
            _latest = default;
            _older = default;
            _segmentCount = 0;
            _accumulator = 0;
            _finished = false;
            _totalSteps = 0;
            _flight?.Reset(start);
            if (_stepper != null)
            {
                // The stepper evaluates the start derivative once; the driver keeps the same one.
                _stepper.Reset(start);
                _derivative = _stepper.Derivative;
            }
            else
            {
                _derivative = Model.Derivative(start);
            }
        }

        /// <summary>
        /// Consumes one frame's time without reporting events (they still happen: read <see cref="IsFinished"/>).
        /// </summary>
        /// <param name="frameDeltaSeconds">The frame's delta time, s; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">The delta is negative, NaN or infinite (nothing is changed).</exception>
        public AdvanceResult Advance(double frameDeltaSeconds) => Advance(frameDeltaSeconds, Span<FrameEvent>.Empty);

        /// <summary>
        /// Consumes one frame's time in fixed steps and writes what happened in them into
        /// <paramref name="events"/>, in time order. Allocates nothing.
        /// </summary>
        /// <param name="frameDeltaSeconds">
        /// The frame's delta time, s (Unity: <c>Time.deltaTime</c>); finite and &gt;= 0. Values above
        /// <see cref="MaxFrameDeltaSeconds"/> are clamped to it.
        /// </param>
        /// <param name="events">Where to write the events; those that do not fit are counted in the result.</param>
        /// <returns>Steps taken, events written and lost, and frame time dropped.</returns>
        /// <exception cref="ArgumentOutOfRangeException">The delta is negative, NaN or infinite (nothing is changed).</exception>
        /// <exception cref="InvalidOperationException">
        /// A fixed step diverged (a plain explicit integrator far beyond its stability limit); the driver is left at
        /// the last good fixed state, with the failed step's time still in the accumulator.
        /// </exception>
        public AdvanceResult Advance(double frameDeltaSeconds, Span<FrameEvent> events)
        {
            if (!double.IsFinite(frameDeltaSeconds) || frameDeltaSeconds < 0)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(frameDeltaSeconds), frameDeltaSeconds,
                    $"frameDeltaSeconds must be a finite frame time >= 0 s; got {Require.Format(frameDeltaSeconds)}.");
            }

            double dropped = 0;
            if (frameDeltaSeconds > MaxFrameDeltaSeconds)
            {
                dropped = frameDeltaSeconds - MaxFrameDeltaSeconds;
                frameDeltaSeconds = MaxFrameDeltaSeconds;
            }

            if (_finished)
            {
                // The flight is over: let the render state run to the end and stay there.
                _accumulator = Math.Min(_accumulator + frameDeltaSeconds, FixedStep);
                return new AdvanceResult(0, 0, 0, dropped + frameDeltaSeconds);
            }

            _accumulator += frameDeltaSeconds;
            int steps = 0;
            int written = 0;
            int lost = 0;
            while (_accumulator >= FixedStep)
            {
                if (steps == MaxStepsPerAdvance)
                {
                    // Substep cap reached: keep the fraction of a step (alpha stays continuous), drop the rest.
                    double keep = _accumulator % FixedStep;
                    dropped += _accumulator - keep;
                    _accumulator = keep;
                    break;
                }

                if (_flight != null)
                {
                    // StepBouncing throws before changing anything when the step diverges.
                    bool stopped = StepBouncing(events, ref written, ref lost);
                    steps++;
                    _totalSteps++;
                    _accumulator -= FixedStep;
                    if (stopped)
                    {
                        break;
                    }

                    continue;
                }

                if (!_stepper!.TryStep(FixedStep))
                {
                    // A refused step changes nothing: the stepper keeps its state, the step's time stays in the accumulator.
                    throw new InvalidOperationException(
                        $"The fixed step of {Require.Format(FixedStep)} s diverged at t = {Require.Format(_state.Time)} s (the state would not be finite): " +
                        $"it is beyond {Integrator.Name}'s stability limit for this ball and speed. Use StableIntegrator.RungeKutta4 " +
                        "(the default of the constructor without an integrator) or a smaller fixed step.");
                }

                steps++;
                _totalSteps++;
                _accumulator -= FixedStep;

                // Events up to the touchdown (those after it lie on the part of the step that never happens).
                Span<FlightEvent> found = SpanView.Of(_stepper.EventsUntil(FlightEventKinds.Landing, out bool landed, out FlightEvent landing));
                foreach (FlightEvent e in found)
                {
                    if (e.Kind != FlightEventKinds.Landing)
                    {
                        FrameEventKind kind = e.Kind == FlightEventKinds.Apex ? FrameEventKind.Apex : FrameEventKind.PlaneCrossing;
                        Write(new FrameEvent(kind, e.PlaneIndex, e.State), events, ref written, ref lost);
                    }
                }

                if (!landed)
                {
                    Push(_stepper.LastSegment);
                    _state = _stepper.State;
                    _derivative = _stepper.Derivative;
                    continue;
                }

                // Touchdown inside this step: cut the step there.
                FlightState touch = landing.State;
                StateDerivative touchDerivative = Model.Derivative(touch);
                if (touch.Time > _state.Time)
                {
                    Push(new HermiteSegment(_state, _derivative, touch, touchDerivative));
                }

                Write(new FrameEvent(FrameEventKind.Landing, -1, touch), events, ref written, ref lost);
                _state = touch;
                _derivative = touchDerivative;
                _finished = true;
                break;
            }

            return new AdvanceResult(steps, written, lost, dropped);
        }

        /// <summary>
        /// One fixed step of the bouncing flight; reports its bounces, and its apex and plane crossings when the
        /// step had no bounce (in a step with a bounce only the bounces are reported). True when the ball stopped.
        /// </summary>
        private bool StepBouncing(Span<FrameEvent> events, ref int written, ref int lost)
        {
            BouncingFlight flight = _flight!;
            FlightState before = flight.State;
            StateDerivative beforeDerivative = flight.Derivative;
            bool wasFlying = flight.Phase == FlightPhase.Flying;
            int bounces = flight.Step(FixedStep, _bounceScratch);

            if (bounces == 0 && wasFlying && flight.Phase == FlightPhase.Flying && _eventSet != null)
            {
                int found = _eventSet.Scan(new HermiteSegment(before, beforeDerivative, flight.State, flight.Derivative), _scratch, startsFlight: _totalSteps == 0);
                for (int i = 0; i < found; i++)
                {
                    FlightEvent e = _scratch[i];
                    if (e.Kind != FlightEventKinds.Landing)
                    {
                        FrameEventKind kind = e.Kind == FlightEventKinds.Apex ? FrameEventKind.Apex : FrameEventKind.PlaneCrossing;
                        Write(new FrameEvent(kind, e.PlaneIndex, e.State), events, ref written, ref lost);
                    }
                }
            }

            for (int i = 0; i < bounces; i++)
            {
                if (i >= _bounceScratch.Length)
                {
                    lost += bounces - i;
                    break;
                }

                BounceEvent b = _bounceScratch[i];
                var incoming = new FlightState(b.Position, b.IncomingVelocity, b.IncomingAngularVelocity, b.Time);
                var outgoing = new FlightState(b.Position, b.Outcome.Velocity, b.Outcome.AngularVelocity, b.Time);
                Write(new FrameEvent(FrameEventKind.Bounce, -1, incoming, outgoing, b.Outcome.Regime, b.StartedRolling), events, ref written, ref lost);
            }

            if (flight.Phase == FlightPhase.Stopped)
            {
                Write(new FrameEvent(FrameEventKind.Stop, -1, flight.State), events, ref written, ref lost);
                _finished = true;
                return true;
            }

            return false;
        }

        private void Push(in HermiteSegment segment)
        {
            _older = _latest;
            _latest = segment;
            _segmentCount = Math.Min(_segmentCount + 1, 2);
        }

        private static void Write(in FrameEvent item, Span<FrameEvent> events, ref int written, ref int lost)
        {
            if (written < events.Length)
            {
                events[written++] = item;
            }
            else
            {
                lost++;
            }
        }

        private static void RequireFiniteState(in FlightState state, string name)
        {
            if (!state.IsFinite)
            {
                throw new ArgumentException($"{name} must have finite position, velocity, angular velocity and time; got {state}.", name);
            }
        }
    }
}
