using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;

namespace MagnusBall.Stepping
{
    /// <summary>
    /// Turns a game engine's variable frame time into fixed integration steps, so that a shot flies the same
    /// path at 30, 60 or 144 frames per second and through hitches: the MonoBehaviour-style adapter. Call
    /// <see cref="Advance(double, Span{FlightEvent})"/> once per frame with the frame's delta time, then draw
    /// the ball at <see cref="RenderState"/>.
    /// </summary>
    /// <remarks>
    /// <para>The pattern is Fiedler's "Fix Your Timestep!" (Gaffer On Games, 2004): frame time goes into an
    /// accumulator; whole fixed steps are taken out of it; what is left (less than one step) says how far
    /// the renderer is between the last two fixed states, alpha = accumulator / step. A frame longer than
    /// <see cref="MaxFrameDeltaSeconds"/> (a hitch: loading, a breakpoint, the window dragged) is clamped, and
    /// at most <see cref="MaxStepsPerAdvance"/> steps are taken per call, so one slow frame cannot trigger
    /// ever more steps (the "spiral of death"); nor more steps once the call has made
    /// <see cref="MaxEvaluationsPerAdvance"/> model evaluations, so a tiny fixed step or a substepping integrator
    /// cannot freeze a frame either. Time that is clamped or capped away is dropped: the ball
    /// falls behind the wall clock but flies exactly the same path, because the path depends only on the
    /// sequence of fixed steps, never on how frame time was sliced.</para>
    /// <para>The seed thesis (Agrawal 2023, section 3.1.3) stepped its ODE once per frame with Unity's
    /// <c>Time.deltaTime</c>, so its landing point depended on the frame rate; docs/unity.md puts numbers
    /// on that difference.</para>
    /// <para>The driver only slices time: each fixed step is one <see cref="FlightStepper.TryStep"/> of the library's
    /// one flight core, which locates the events (landing, bounces, apex, plane crossings) on the step's dense
    /// output and applies them; the driver copies them to a caller-provided buffer. Without a bounce model the
    /// flight ends at the first landing (the last step is cut there). With one, the ball bounces at the located
    /// contact time and the step is finished from there, so the fixed time grid is kept; the ball rolls once a
    /// bounce is too weak and the flight ends when it comes to rest. A step whose state would not be finite (an
    /// explicit method far beyond its stability limit, once its growth overflows) or whose clock cannot advance is refused (the
    /// state stays the last finite one), reported in <see cref="AdvanceResult.Diverged"/> and ends the flight. An unstable
    /// method's growth is not detected while it stays finite (a 1 g ball on explicit Euler at 0.1 s "landed" at 4.6e6 m/s
    /// after two steps): the default <see cref="StableIntegrator.RungeKutta4"/> substeps so that it does not arise.
    /// Nothing here allocates after construction.</para>
    /// <para>A driver owns its state and is not thread-safe; the model, integrator, event set and bounce
    /// model it uses are immutable and may be shared by any number of drivers on any threads.</para>
    /// </remarks>
    public sealed class FixedStepDriver
    {
        /// <summary>The default frame-time clamp, 0.25 s (Fiedler 2004).</summary>
        public const double DefaultMaxFrameDeltaSeconds = 0.25;

        /// <summary>
        /// The work cap of one <see cref="Advance(double, Span{FlightEvent})"/> call: once its steps have made this many
        /// model evaluations plus steps (250,000; a step's own work, its dense output and event scan, costs about one
        /// evaluation; up to 1 s on a loaded core), it takes no more steps and drops the frame time left, as at
        /// <see cref="MaxStepsPerAdvance"/>. A game never meets it (RK4 at 1/240 s through a 0.25 s hitch makes 305); it bounds a tiny fixed step (1e-9 s: 2.5e8 steps in one clamped frame) and a step that
        /// <see cref="StableIntegrator"/> splits into thousands of substeps. A step in progress is finished, so a call can
        /// exceed it by one step's work (at most <see cref="FlightStepper.MaxPiecesPerStep"/> pieces of
        /// <see cref="StableStepping.MaximumSubsteps"/> substeps).
        /// </summary>
        internal const long MaxEvaluationsPerAdvance = 250_000;

        private readonly FlightStepper _stepper;
        private readonly FlightEventKinds _stopAt;
        private double _accumulator;
        private bool _diverged;

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
        /// radius below it), rolls when a bounce leaves slower than <paramref name="restNormalSpeed"/>, and the
        /// flight ends when it comes to rest.
        /// </param>
        /// <param name="maxFrameDeltaSeconds">The frame-time clamp, s; finite and &gt; 0. Default 0.25 s.</param>
        /// <param name="maxStepsPerAdvance">
        /// The most fixed steps one <see cref="Advance(double, Span{FlightEvent})"/> call takes; &gt;= 1, or 0
        /// (the default) for ceil(maxFrameDeltaSeconds / fixedStep) + 1, so that the clamp binds first.
        /// </param>
        /// <param name="restNormalSpeed">With a bounce model: bounces leaving slower than this along the normal start rolling, m/s; finite, &gt;= 0.</param>
        /// <param name="rollingResistance">With a bounce model: the rolling-resistance coefficient (see <see cref="GroundContact"/>); finite, &gt;= 0.</param>
        /// <param name="shapes">Shapes the ball can hit (see <see cref="FlightStepper"/>'s constructor), copied; or null for none.</param>
        /// <exception cref="ArgumentNullException">model or integrator is null.</exception>
        /// <exception cref="ArgumentException">
        /// A number is out of its range (the message names it), there is a bounce model but no ground, or a shape is null.
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
            double restNormalSpeed = GroundContact.DefaultRestNormalSpeed,
            double rollingResistance = GroundContact.DefaultRollingResistance,
            ContactShape[]? shapes = null)
        {
            Require.NotNull(model, nameof(model));
            Require.NotNull(integrator, nameof(integrator));
            FixedStep = Require.Step(fixedStep, nameof(fixedStep));
            Require.FiniteState(start, nameof(start));
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

            FlightEventSet? eventSet = events ?? (model.Up.LengthSquared > 0 ? FlightEventSet.ForModel(model) : null);
            GroundContact? contact = null;
            if (bounce != null)
            {
                if (eventSet?.Ground == null)
                {
                    throw new ArgumentException("bounce needs a ground plane to bounce on: give events with a ground (or a model with gravity).", nameof(bounce));
                }

                // The event set's ground is where the ball's centre touches down; the court lies one radius below.
                Plane ground = eventSet.Ground.Value;
                var court = new Plane(ground.Point - ground.Normal * model.Ball.Radius, ground.Normal);
                contact = new GroundContact(bounce, court, restNormalSpeed, rollingResistance);
            }

            _stepper = new FlightStepper(model, integrator, eventSet, contact, shapes);
            _stopAt = contact == null ? FlightEventKinds.Landing : FlightEventKinds.None;
            Reset(start);
        }

        /// <summary>The flight model being stepped.</summary>
        internal FlightModel Model => _stepper.Model;

        /// <summary>The integrator.</summary>
        internal IIntegrator Integrator => _stepper.Integrator;

        /// <summary>The fixed step, s.</summary>
        public double FixedStep { get; }

        /// <summary>The frame-time clamp, s.</summary>
        internal double MaxFrameDeltaSeconds { get; }

        /// <summary>The most fixed steps one Advance call takes.</summary>
        public int MaxStepsPerAdvance { get; }

        /// <summary>What the driver looks for in each step (null: nothing).</summary>
        internal FlightEventSet? Events => _stepper.EventSet;

        /// <summary>The bounce model, or null when the flight ends at the first landing.</summary>
        internal IBounceModel? BounceModel => _stepper.Contact?.Bounce;

        /// <summary>Flying, rolling or stopped.</summary>
        public FlightPhase Phase => _stepper.Phase;

        /// <summary>The latest fixed state (the simulation's "now"); at the end, the landing or the rest.</summary>
        public FlightState State => _stepper.State;

        /// <summary>The start of the latest step (equal to <see cref="State"/> before the first step).</summary>
        internal FlightState PreviousState => _stepper.PreviousState;

        /// <summary>
        /// Frame time not yet simulated, s: in [0, <see cref="FixedStep"/>) while flying, except after a call that deferred steps
        /// (<see cref="AdvanceResult.StepsDeferred"/>), which leaves the deferred time here until a later call takes it.
        /// </summary>
        internal double Accumulator => _accumulator;

        /// <summary>
        /// accumulator / step, in [0, 1]: how far the render state is through the last step while it was a whole one (a step
        /// cut short by its stop is drawn at RenderState.Time, State.Time - step + accumulator, not at this fraction of it).
        /// </summary>
        public double Alpha => Math.Min(1.0, _accumulator / FixedStep);

        /// <summary>
        /// True once the flight has ended: landed without a bounce model, at rest after bounces and rolling, or refused
        /// a diverging step (<see cref="Diverged"/>). Advance takes no more steps.
        /// </summary>
        public bool IsFinished => _stepper.IsStopped || _diverged;

        /// <summary>
        /// True when a fixed step was refused because its state was not finite (an integrator beyond its stability limit,
        /// once its growth overflows) or its clock could not advance (a start time near 1e20 s): the flight ended at the
        /// last finite state. Growth that stays finite is not detected (see the class remarks).
        /// </summary>
        public bool Diverged => _diverged;

        /// <summary>Fixed steps taken since the last reset.</summary>
        internal long TotalSteps => _stepper.StepCount;

        /// <summary>Bounces since the last reset.</summary>
        internal int Bounces => _stepper.BounceCount;

        /// <summary>Model evaluations since the last reset (counted by the flight core: each is one call of the model).</summary>
        internal long DerivativeEvaluations => _stepper.DerivativeEvaluations;

        /// <summary>
        /// The simulation time the renderer should show, s: one fixed step behind the simulation,
        /// State.Time - step + accumulator, never past <see cref="State"/> and never before the start.
        /// </summary>
        internal double RenderTime => RenderState.Time;

        /// <summary>
        /// The state to draw this frame, at RenderState.Time: on the cubic Hermite of the step it falls
        /// in (both ends' states and derivatives, so the drawn path is C1 and keeps the curvature a linear blend
        /// of the two fixed states would cut), split at bounces. Allocates nothing.
        /// </summary>
        public FlightState RenderState
        {
            get
            {
                FlightState now = _stepper.State;
                if (_stepper.StepCount == 0)
                {
                    return now;
                }

                // In the last step: a step's time comes out of the accumulator only once the accumulator holds it (a step cut
                // short by its stop takes out only the time it flew), so the render time is never before the last step's start
                // (to rounding, where StateAt gives the start).
                double time = Math.Min(now.Time, now.Time - FixedStep + _accumulator);
                return _stepper.StateAt(time);
            }
        }

        /// <summary>Starts a new flight from <paramref name="start"/>: state, accumulator and counters reset.</summary>
        /// <param name="start">The launch state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite, or (with a bounce model) it lies on the court and the roll it starts would not be finite (nothing changes).</exception>
        public void Reset(in FlightState start)
        {
            Require.FiniteState(start, nameof(start));
            _stepper.Reset(start);
            _accumulator = 0;
            _diverged = false;
        }

        /// <summary>Advances by one frame without reporting events (see <see cref="Advance(double, Span{FlightEvent})"/>).</summary>
        /// <param name="frameDeltaSeconds">The frame's delta time, s; finite and &gt;= 0.</param>
        /// <returns>What the call did.</returns>
        /// <exception cref="ArgumentOutOfRangeException">frameDeltaSeconds is negative or not finite (nothing changes).</exception>
        public AdvanceResult Advance(double frameDeltaSeconds) => Advance(frameDeltaSeconds, Span<FlightEvent>.Empty);

        /// <summary>
        /// Advances by one frame: adds the (clamped) frame time to the accumulator, takes the whole fixed steps it
        /// holds (at most <see cref="MaxStepsPerAdvance"/>, and none once the call has made
        /// <see cref="MaxEvaluationsPerAdvance"/> model evaluations plus steps plus pieces of the shapes' touch searches), and writes the
        /// events of those steps, in time order,
        /// into <paramref name="events"/>. Allocates nothing.
        /// </summary>
        /// <param name="frameDeltaSeconds">The frame's delta time, s; finite and &gt;= 0 (Unity: Time.deltaTime).</param>
        /// <param name="events">Where to write the events (may be empty). With at least <see cref="MaximumEventsPerStep"/> slots none is
        /// ever lost: the call stops before a step whose events might not fit and keeps that time
        /// (<see cref="AdvanceResult.StepsDeferred"/>; call again with 0 to go on). With fewer, those that do not fit are counted in
        /// <see cref="AdvanceResult.EventsNotReported"/>.</param>
        /// <returns>What the call did.</returns>
        /// <exception cref="ArgumentOutOfRangeException">frameDeltaSeconds is negative or not finite (nothing changes).</exception>
        public AdvanceResult Advance(double frameDeltaSeconds, Span<FlightEvent> events)
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

            if (IsFinished)
            {
                // The flight is over: let the render state run to the end and stay there.
                _accumulator = Math.Min(_accumulator + frameDeltaSeconds, FixedStep);
                return new AdvanceResult(0, 0, 0, dropped + frameDeltaSeconds, _diverged);
            }

            _accumulator += frameDeltaSeconds;
            int steps = 0, written = 0, lost = 0;
            int perStep = _stepper.MaximumEventsPerStep;
            bool deferrable = events.Length >= perStep; // a buffer that holds any one step's events: never lose one
            bool deferred = false;
            long workBefore = _stepper.Work;
            bool lookAhead = true;
            // Bounded by MaxStepsPerAdvance and by MaxEvaluationsPerAdvance.
            while (_accumulator >= FixedStep)
            {
                long work = _stepper.Work - workBefore; // this call's so far
                if (steps == MaxStepsPerAdvance || work >= MaxEvaluationsPerAdvance)
                {
                    // Step or work cap reached: keep the fraction of a step (alpha stays continuous), drop the rest.
                    double keep = _accumulator % FixedStep;
                    dropped += _accumulator - keep;
                    _accumulator = keep;
                    break;
                }

                if (deferrable && events.Length - written < perStep)
                {
                    // The next step's events might not fit: keep its time for the next call (the render state holds at the
                    // current state meanwhile, Alpha being capped at 1).
                    deferred = true;
                    break;
                }

                // The steps this loop would start from here if each were quiet (no event, plain RK4): taken in one stepper call,
                // the same steps as one TryStep call each (FlightStepper.TrySteps), which returns after the first step that is
                // not quiet; that step is then handled below as the loop handled every step. Looked ahead only where steps can
                // be quiet and the last call took one (otherwise one step a call, as TryStep), so a flight whose steps are not
                // quiet (a bounce model, another method, events step after step) pays nothing for it.
                int allowed = lookAhead && _stepper.StepsQuietly ? StepsAllowed(steps, work) : 1;
                StepOutcome outcome = _stepper.TrySteps(FixedStep, _stopAt, allowed, out int quiet, out double stepStart);
                for (int i = 0; i < quiet; i++)
                {
                    _accumulator -= FixedStep;
                }

                steps += quiet;
                lookAhead = quiet > 0;
                if (quiet == allowed)
                {
                    continue; // every step quiet: no other step was attempted
                }

                if (outcome == StepOutcome.Diverged || outcome == StepOutcome.TimeCannotAdvance)
                {
                    // Refused: the stepper kept its last finite state. The flight ends there, and the render time runs on to it:
                    // the accumulator holds at least a step, of which one is kept (RenderTime = State.Time, reached by at most
                    // this frame's time) and the rest dropped. Emptied, it would put the render time back at the last step's
                    // start, the drawn ball jumping back a step.
                    _diverged = true;
                    dropped += _accumulator - FixedStep;
                    _accumulator = FixedStep;
                    break;
                }

                steps++;
                // A step cut short by its stop event (a landing) uses only the time it flew: the render clock (RenderTime) then
                // goes on by the frame time through this frame, to the stop, instead of losing the rest of the step.
                _accumulator -= _stepper.IsStopped ? _stepper.CurrentTime - stepStart : FixedStep;
                foreach (FlightEvent e in SpanView.Of(_stepper.Events)) // not ReadOnlySpan's enumerator: Mono 6.8 lacks it
                {
                    if (written < events.Length)
                    {
                        events[written++] = e;
                    }
                    else
                    {
                        lost++;
                    }
                }

                if (_stepper.IsStopped)
                {
                    break;
                }
            }

            return new AdvanceResult(steps, written, lost, dropped, _diverged, deferred);
        }

        // The most steps Advance asks of the stepper in one call: it bounds the look-ahead below (a frame of more steps takes more
        // calls), so that a flight whose quiet runs are cut short often pays at most this many turns of it a step.
        private const int MaxQuietRun = 16;

        // How many steps in a row the loop in Advance would start from here (its tests passed for the first) if each were a quiet
        // one, which subtracts FixedStep from the accumulator and adds FlightStepper.QuietStepWork to the work: the same tests,
        // made ahead on copies. At least 1, at most MaxQuietRun and MaxStepsPerAdvance - steps.
        private int StepsAllowed(int steps, long work)
        {
            double accumulator = _accumulator - FixedStep;
            int allowed = 1;
            while (allowed < MaxQuietRun && accumulator >= FixedStep && steps + allowed < MaxStepsPerAdvance &&
                work + (long)allowed * FlightStepper.QuietStepWork < MaxEvaluationsPerAdvance)
            {
                accumulator -= FixedStep;
                allowed++;
            }

            return allowed;
        }

        /// <summary>
        /// The most events one fixed step can report (<see cref="FlightStepper.MaximumEventsPerStep"/>): an events buffer this
        /// long (or longer) never loses one (<see cref="AdvanceResult.StepsDeferred"/>).
        /// </summary>
        public int MaximumEventsPerStep => _stepper.MaximumEventsPerStep;
    }
}
