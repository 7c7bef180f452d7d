using System;
using System.Runtime.CompilerServices;
using MagnusBall.Contact;
using MagnusBall.Integration;

namespace MagnusBall.Flight
{
    /// <summary>How a ball moves: flying, rolling on a contact surface, or stopped.</summary>
    public enum FlightPhase
    {
        /// <summary>In the air (free flight under gravity, drag and Magnus).</summary>
        Flying = 0,

        /// <summary>Rolling on the contact surface.</summary>
        Rolling = 1,

        /// <summary>Stopped: at rest on the surface, or the flight ended at a stop event (a landing).</summary>
        Stopped = 2,
    }

    /// <summary>What one call of <see cref="FlightStepper.TryStep"/> did.</summary>
    public enum StepOutcome
    {
        /// <summary>The step was taken; its events are in <see cref="FlightStepper.Events"/>.</summary>
        Taken = 0,

        /// <summary>The step was taken and ended at a stop event (or the ball came to rest): the flight is over.</summary>
        Stopped = 1,

        /// <summary>
        /// Refused: the step would make the state or its derivative non-finite (far beyond the integrator's stability
        /// limit). Nothing changed.
        /// </summary>
        Diverged = 2,

        /// <summary>
        /// Refused: the clock cannot advance (the time is so large that adding the step does not change it). Nothing
        /// changed. The state is finite: this is not a divergence; restart the flight at a smaller time.
        /// </summary>
        TimeCannotAdvance = 3,

        /// <summary>Nothing to do: the flight was already over (<see cref="FlightStepper.IsStopped"/>).</summary>
        AlreadyStopped = 4,
    }

    /// <summary>
    /// The one stepping loop of the library: it steps one ball's flight, locates every event on each step's dense
    /// output, applies each event's effect (stop at a landing, bounce and roll on a <see cref="GroundContact"/>,
    /// continue past an apex or a plane crossing), finishes the rest of the step, and refuses a diverging step. The
    /// trajectory predictor, the aim solvers, the fixed-step driver, the CLI and the benchmarks all fly through it.
    /// </summary>
    /// <remarks>
    /// <para><b>One step, top to bottom</b> (<see cref="TryStep"/>): integrate from the current state and its
    /// derivative (the integrator returns the end state with its end derivative, so no point is evaluated twice);
    /// build the step's cubic Hermite; find the events on it (the ground or contact plane, the apex, each watched
    /// plane) in time order; take the first one with an effect: a stop event ends the flight at its instant, a
    /// contact bounces the ball there and the loop integrates the rest of the step from the bounce; a roll or a rest
    /// finishes the step on the surface. Events are written into the stepper's array during the step (Box2D style)
    /// and read afterwards through <see cref="Events"/>.</para>
    /// <para><b>Costs.</b> <see cref="DerivativeEvaluations"/> adds what each integrator call reports, plus one
    /// evaluation at each restart (the start, a bounce). A fixed step without events costs exactly the
    /// integrator's <see cref="IIntegrator.DerivativeEvaluationsPerStep"/>.</para>
    /// <para><b>Bounds.</b> A step holds at most <see cref="MaxPiecesPerStep"/> pieces of flight between bounces;
    /// at the last one the ball is put to rolling. <see cref="TryStepAdaptive"/> retries a rejected adaptive step at
    /// most <see cref="MaxAdaptiveAttempts"/> times. Nothing here loops without a cap.</para>
    /// <para><b>Failure.</b> A refused step (<see cref="StepOutcome.Diverged"/>, <see cref="StepOutcome.TimeCannotAdvance"/>)
    /// and every call that throws leave the stepper exactly as it was.</para>
    /// <para>Not thread-safe: one stepper per ball. The model, integrator, event set and contact it holds are
    /// immutable and may be shared.</para>
    /// </remarks>
    public sealed class FlightStepper
    {
        /// <summary>The most pieces of flight (between bounces) one step holds; the last puts the ball to rolling.</summary>
        public const int MaxPiecesPerStep = 16;

        /// <summary>The most attempts <see cref="TryStepAdaptive"/> makes before it accepts the smallest step it tried.</summary>
        public const int MaxAdaptiveAttempts = 64;

        // Two of each: a step writes its events and pieces into the pending arrays and swaps them in when it is taken,
        // so a refused step leaves the last step's Events and segments exactly as they were.
        private FlightEvent[] _events;
        private FlightEvent[] _pendingEvents;
        private readonly FlightEvent[] _scratch;
        private HermiteSegment[] _segments = new HermiteSegment[MaxPiecesPerStep + 1];
        private HermiteSegment[] _pendingSegments = new HermiteSegment[MaxPiecesPerStep + 1];
        private readonly Plane _contactPlane;
        private readonly Vector3d _normal;
        private readonly double _rollingDeceleration; // c_rr g_n
        private readonly bool _canRest;               // the slope alone cannot keep the ball moving against rolling resistance
        private readonly bool _gravityHolds;          // gravity pushes the ball into the surface

        private Snapshot _now;
        // Where a fixed step goes straight to the model's RK4 kernel (IntegrateFixed): plain RK4, or the stable RK4 with RK4 inside
        // wherever its step is one substep. Fixed here, as the integrator is.
        private readonly bool _plainRk4;
        private readonly StableIntegrator? _stableRk4;
        private Snapshot _before; // Advance's copy of _now from before the step (scratch: see there)
        private FlightEvent _stopEvent;        // the flight's stop event (outside the snapshot: set only by a step that stops)
        private FlightEvent _pendingStop;      // a stop found during the step, committed with it
        // The last step's dense output is its one piece (Previous, PreviousDerivative, State, Derivative), not stored in
        // _segments: the common step (one piece, no event with an effect) copies no segment.
        private bool _implicitSegment;
        private bool _pendingImplicit;
        // The first piece of a step that TryStep integrated before handing the step to Advance (it held an event).
        private FlightState _firstPiece;
        private StateDerivative _firstPieceDerivative;
        private int _firstPieceEvaluations;
        private bool _hasFirstPiece;
        private int _eventCount;
        private int _segmentCount;
        private int _pendingEventCount;
        private int _pendingSegmentCount;
        private bool _started;
        private StepOutcome _refusal; // why the last piece that returned false refused the step
        private DormandPrince54Step _adaptiveStep; // the last adaptive step attempted (scratch: TryStepAdaptive fills it in place)

        /// <summary>Creates a stepper; call <see cref="Reset"/> to give it a state.</summary>
        /// <param name="model">The flight model.</param>
        /// <param name="integrator">The integration method.</param>
        /// <param name="events">What to look for in each step (ground, apex, planes), or null for no events.</param>
        /// <param name="contact">A surface to bounce and roll on, or null (then touching the event set's ground is a landing).</param>
        /// <exception cref="ArgumentNullException">model or integrator is null.</exception>
        public FlightStepper(FlightModel model, IIntegrator integrator, FlightEventSet? events = null, GroundContact? contact = null)
        {
            Model = Require.NotNull(model, nameof(model));
            Integrator = Require.NotNull(integrator, nameof(integrator));
            _plainRk4 = integrator is RungeKutta4;
            _stableRk4 = integrator is StableIntegrator stable && stable.Inner is RungeKutta4 ? stable : null;
            EventSet = events;
            Contact = contact;
            int perPiece = (events?.MaximumEventsPerStep ?? 0) + 1;
            _events = new FlightEvent[(MaxPiecesPerStep + 1) * perPiece + 1];
            _pendingEvents = new FlightEvent[_events.Length];
            _scratch = new FlightEvent[perPiece];
            if (contact != null)
            {
                _normal = contact.Plane.Normal;
                _contactPlane = new Plane(contact.Plane.Point + _normal * model.Ball.Radius, _normal);
                double gn = -Vector3d.Dot(model.Gravity, _normal);
                Vector3d gt = model.Gravity + _normal * gn;
                _rollingDeceleration = contact.RollingResistance * Math.Max(gn, 0);
                _gravityHolds = gn > 0;
                _canRest = gt.Length / (1 + model.Ball.InertiaFactor) <= _rollingDeceleration;
            }
        }

        /// <summary>The flight model.</summary>
        public FlightModel Model { get; }

        /// <summary>The integration method.</summary>
        public IIntegrator Integrator { get; }

        /// <summary>The events looked for in each step, or null.</summary>
        public FlightEventSet? EventSet { get; }

        /// <summary>The surface the ball bounces and rolls on, or null.</summary>
        public GroundContact? Contact { get; }

        /// <summary>The current state (the end of the last step, or the stop).</summary>
        public FlightState State => _now.State;

        // The current state by reference and its time, for the library's own loops: State returns an 80-byte copy, which
        // Mono's JIT zeroes before it fills it.
        internal ref readonly FlightState CurrentState => ref _now.State;

        internal double CurrentTime => _now.State.Time;

        /// <summary>
        /// The derivative at the current state (the next step's start derivative). After a stop at an event, the slope of
        /// the step's dense output there (the flight is over; no evaluation is spent on it); at rest, zero.
        /// </summary>
        public StateDerivative Derivative => _now.Derivative;

        /// <summary>The state at the start of the last step.</summary>
        public FlightState PreviousState => _now.Previous;

        /// <summary>Flying, rolling or stopped.</summary>
        public FlightPhase Phase => _now.Phase;

        /// <summary>True once the flight is over: stopped at a stop event, or at rest.</summary>
        public bool IsStopped => _now.Phase == FlightPhase.Stopped;

        /// <summary>The dense output of the last piece of flight of the last step (default before the first step).</summary>
        internal HermiteSegment LastSegment =>
            _implicitSegment ? HermiteSegment.OfTakenStep(_now.Previous, _now.PreviousDerivative, _now.State, _now.Derivative)
            : _segmentCount > 0 ? _segments[_segmentCount - 1] : default;

        /// <summary>
        /// The most events one step can report: every piece between bounces (at most <see cref="MaxPiecesPerStep"/> + 1) with
        /// each of its events, and the rest. A buffer this long holds any step's <see cref="Events"/>.
        /// </summary>
        public int MaximumEventsPerStep => _events.Length;

        /// <summary>
        /// The events of the last step taken, in time order, up to its stop event (nothing after a stop happens). A refused
        /// step leaves them as they were; a call on a stopped flight (<see cref="StepOutcome.AlreadyStopped"/>) clears them.
        /// </summary>
        public ReadOnlySpan<FlightEvent> Events => _eventCount == 0 ? default : new ReadOnlySpan<FlightEvent>(_events, 0, _eventCount);

        /// <summary>How many events the last step found (<see cref="Events"/>' length, without building the span).</summary>
        internal int EventCount => _eventCount;

        /// <summary>The stop event of the flight (default until <see cref="IsStopped"/>; a rest is a stop too).</summary>
        public FlightEvent StopEvent => _stopEvent;

        /// <summary>Steps taken since the last <see cref="Reset"/>.</summary>
        public long StepCount => _now.Steps;

        /// <summary>Bounces since the last <see cref="Reset"/>.</summary>
        public int BounceCount => _now.Bounces;

        /// <summary>Model evaluations since the last <see cref="Reset"/> (including the one at the start state).</summary>
        public long DerivativeEvaluations => _now.Evaluations;

        /// <summary>
        /// Starts a new flight from <paramref name="state"/>: sets the state, evaluates its derivative, zeroes the
        /// counters. A ball placed exactly on the ground or a watched plane and heading through it crosses it at the
        /// start of the next step; with a contact, a ball placed on the surface and not leaving it rolls (or rests).
        /// </summary>
        /// <param name="state">The start state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite, or it lies on the contact surface and the roll it
        /// starts would not be finite (nothing changes).</exception>
        public void Reset(in FlightState state)
        {
            Require.FiniteState(state, nameof(state));
            Restart(state, zeroCounters: true);
        }

        /// <summary>
        /// Replaces the current state mid-flight (a hit, a teleport) without zeroing the counters: one evaluation.
        /// As after <see cref="Reset"/>, a state exactly on a plane and heading through it crosses it at the start of
        /// the next step.
        /// </summary>
        /// <param name="state">The new state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite, or it lies on the contact surface and the roll it
        /// starts would not be finite (nothing changes).</exception>
        public void SetState(in FlightState state)
        {
            Require.FiniteState(state, nameof(state));
            Restart(state, zeroCounters: false);
        }

        private void Restart(in FlightState state, bool zeroCounters)
        {
            Snapshot saved = _now;
            int events = _eventCount, segments = _segmentCount;
            bool started = _started, implicitSegment = _implicitSegment;
            FlightEvent stopEvent = _stopEvent;
            // Evaluated before anything changes: a user's law that throws leaves the flight as it was.
            StateDerivative derivative = Model.Derivative(state);
            if (zeroCounters)
            {
                _now = default;
            }

            _now.State = state;
            _now.Previous = state;
            _now.Derivative = derivative;
            _now.PreviousDerivative = derivative;
            _now.Evaluations++;
            _now.Phase = FlightPhase.Flying;
            _now.StartsFlight = true;
            _stopEvent = default;
            _eventCount = 0;
            _segmentCount = 0;
            _implicitSegment = false;
            _hasFirstPiece = false;
            _started = true;
            if (Contact != null && _gravityHolds && _contactPlane.SignedDistance(state.Position) <= 0 && Vector3d.Dot(state.Velocity, _normal) <= 0)
            {
                // Placed on the surface (or in it) and not leaving it: it rolls from there, or rests.
                bool finite;
                try
                {
                    StartRolling(_contactPlane.Project(state.Position), state.Velocity, state.AngularVelocity, state.Time);
                    finite = _now.State.IsFinite && _now.Derivative.IsFinite;
                }
                catch
                {
                    PutBack(); // a user's model threw: everything put back, then its exception let through
                    throw;
                }

                if (!finite)
                {
                    // The roll it starts overflows: refused, and everything is put back.
                    PutBack();
                    throw new ArgumentException(
                        $"state is on the contact surface, and the roll it starts would not be finite (its speed, spin or rolling acceleration exceeds double); got {state}.",
                        nameof(state));
                }
            }

            void PutBack()
            {
                _now = saved;
                _eventCount = events;
                _segmentCount = segments;
                _started = started;
                _implicitSegment = implicitSegment;
                _stopEvent = stopEvent;
            }
        }

        /// <summary>
        /// Advances the flight by <paramref name="step"/> seconds (less when it stops at an event of the
        /// <paramref name="stopAt"/> kinds), locating and applying every event inside. Allocates nothing.
        /// </summary>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="stopAt">The event kinds that end the flight (for example <see cref="FlightEventKinds.Landing"/>);
        /// a rest always does.</param>
        /// <returns>What happened; a refused step (<see cref="StepOutcome.Diverged"/>, <see cref="StepOutcome.TimeCannotAdvance"/>) changes nothing.</returns>
        /// <exception cref="InvalidOperationException">No state was given yet (<see cref="Reset"/>).</exception>
        /// <exception cref="ArgumentOutOfRangeException">The step is not finite and positive.</exception>
        public StepOutcome TryStep(double step, FlightEventKinds stopAt = FlightEventKinds.None)
        {
            RequireStarted();
            Require.Step(step, nameof(step));
            return Steps(step, stopAt, 1, out _, out _);
        }

        /// <summary>
        /// Up to <paramref name="count"/> steps of <paramref name="step"/> seconds in one call (<see cref="Stepping.FixedStepDriver"/>'s
        /// frame): the same steps, bits and counts as that many <see cref="TryStep"/> calls, up to and including the first step
        /// that is not quiet. A quiet step is TryStep's common step by plain RK4 (or the stable RK4 in one substep): in flight
        /// with no contact, taken in one piece, surely no event on it. Quiet steps hand their end to the next step in locals and
        /// are committed together, where TryStep commits each into the stepper's fields. The first step that is not quiet (an
        /// event may lie on it, it is refused, it takes another method or more substeps) is taken as TryStep takes it, and the
        /// call returns after it with its outcome.
        /// </summary>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="stopAt">As <see cref="TryStep"/>'s.</param>
        /// <param name="count">The most steps, at least 1: the caller bounds it (the driver by its step and work caps, each quiet step
        /// costing <see cref="QuietStepWork"/>).</param>
        /// <param name="quiet">The quiet steps taken. <paramref name="count"/> when every step was quiet (the outcome is then
        /// <see cref="StepOutcome.Taken"/>); otherwise one more step was attempted after them, and the outcome is its own.</param>
        /// <param name="lastStart">The time at the start of the last step attempted.</param>
        /// <remarks>
        /// A law of the user's that throws does so while a step is integrated, before the call commits anything: the exception
        /// goes through with the stepper as the call found it (TryStep calls would have kept the steps before the throwing one).
        /// The one other code a step here runs, the event scan and the stop at a landing, calls no user code: bounces and rolls,
        /// which do, need a contact surface, and with one no step is quiet.
        /// </remarks>
        internal StepOutcome TrySteps(double step, FlightEventKinds stopAt, int count, out int quiet, out double lastStart)
        {
            RequireStarted();
            Require.Step(step, nameof(step));
            return Steps(step, stopAt, Math.Max(count, 1), out quiet, out lastStart);
        }

        /// <summary>The work (evaluations plus one step) of one quiet step of <see cref="TrySteps"/>.</summary>
        internal const int QuietStepWork = RungeKutta4.Evaluations + 1;

        /// <summary>
        /// Whether the next step may be quiet (<see cref="TrySteps"/>): in flight, no contact surface, and plain RK4 or the
        /// stable RK4 with RK4 inside. Where it is false every step is taken the general way, one a call.
        /// </summary>
        internal bool StepsQuietly => Contact == null && _now.Phase == FlightPhase.Flying && (_plainRk4 || _stableRk4 != null);

        // How a fixed step from a state came out (IntegrateFixed).
        private enum FixedStepKind
        {
            Quiet,           // taken, by the RK4 kernel in one piece, and surely no event on it
            Plain,           // taken the same way by another method (or substeps): no event surely, but not a quiet step
            MaybeEvents,     // finite, but an event may lie on it (the full scan decides)
            Diverged,        // its end or end derivative is not finite (refused)
            TimeCannotAdvance,
        }

        // TryStep's and TrySteps' steps. The common step first: one piece, and, when it holds no event, taken at once (nothing to
        // put back if it were refused, so no snapshot). Where it holds an event, the general step takes this integration as its
        // first piece: the step is integrated once either way.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private StepOutcome Steps(double step, FlightEventKinds stopAt, int count, out int quiet, out double lastStart)
        {
            quiet = 0;
            lastStart = _now.State.Time;
            if (Contact != null || _now.Phase != FlightPhase.Flying)
            {
                return Advance(step, stopAt, adaptive: null);
            }

            if (count > 1)
            {
                return QuietSteps(step, stopAt, count, out quiet, out lastStart);
            }

            // Integrated straight into the first-piece fields (meaningful only once _hasFirstPiece is set): Mono zeroes every
            // struct local on entry, and these two are 152 bytes.
            FixedStepKind kind = IntegrateFixed(_now.State, _now.Derivative, step, out _firstPiece, out _firstPieceDerivative, out int evaluations);

            if (kind == FixedStepKind.Quiet)
            {
                quiet = 1;
            }

            return Finish(kind, step, stopAt, evaluations);
        }

        // One fixed step from (start, startDerivative), integrated into (next, nextDerivative) as TryStep's common step takes it.
        // The built-in RK4 goes straight to the model's kernel (no argument check: the state is finite, as every state this class
        // takes, and the step was checked; no interface call), and so does the stable RK4 where its step is one substep; every
        // other method, and the stable RK4's substepped steps, through IIntegrator.Step. next must not be start.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private FixedStepKind IntegrateFixed(
            in FlightState start, in StateDerivative startDerivative, double step, out FlightState next, out StateDerivative nextDerivative, out int evaluations)
        {
            double endTime = start.Time + step;
            if (!(endTime > start.Time))
            {
                next = start;
                nextDerivative = startDerivative;
                evaluations = 0;
                return FixedStepKind.TimeCannotAdvance;
            }

            evaluations = RungeKutta4.Evaluations;
            bool kernel = _plainRk4 || (_stableRk4 != null && StableStepping.SubstepsFor(Model, start, step, _stableRk4.StiffnessLimit) == 1);
            if (kernel)
            {
                // Plain RK4, or the stable RK4's common case: StableStepping.Step's one substep, the whole step, counted by the
                // same method (its result is that RK4 step with the time set to the step's end, as here below).
                RungeKutta4.StepCheckedInto(Model, start, startDerivative, step, out next, out nextDerivative);
            }
            else
            {
                next = Integrator.Step(Model, start, startDerivative, step, out nextDerivative, out evaluations);
            }

            if (!Takes(start, next, nextDerivative))
            {
                return FixedStepKind.Diverged; // nothing changed
            }

            if (next.Time != endTime)
            {
                next = new FlightState(next.Position, next.Velocity, next.AngularVelocity, endTime);
            }

            if (EventSet != null && !EventSet.SurelyClear(start, startDerivative, next, nextDerivative))
            {
                return FixedStepKind.MaybeEvents;
            }

            return kernel ? FixedStepKind.Quiet : FixedStepKind.Plain;
        }

        // The step integrated into the first-piece fields from the current state, taken as TryStep takes it.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private StepOutcome Finish(FixedStepKind kind, double step, FlightEventKinds stopAt, int evaluations)
        {
            switch (kind)
            {
                case FixedStepKind.Diverged:
                    return StepOutcome.Diverged;
                case FixedStepKind.TimeCannotAdvance:
                    return StepOutcome.TimeCannotAdvance;
                case FixedStepKind.MaybeEvents:
                    if (ScansClear(_firstPiece, _firstPieceDerivative))
                    {
                        break;
                    }

                    _firstPieceEvaluations = evaluations;
                    _hasFirstPiece = true;
                    return Advance(step, stopAt, adaptive: null);
            }

            TakePlainStep(_firstPiece, _firstPieceDerivative, evaluations);
            return StepOutcome.Taken;
        }

        // TrySteps' steps for a count of two or more. Three slots in turn, a, b and c, each a state and its derivative: each step
        // reads the last step's end and writes the slot that holds neither that end nor its start, so no state is copied from
        // step to step, and when a step is not quiet the last quiet step's start and end are both at hand to commit. The current
        // state, the first step's start, is not written before the commit. Out of line: Mono zeroes every struct local on entry
        // (456 bytes here), which a single step (TryStep) should not pay. Each QuietStep takes a step or ends the call, and it
        // ends once count steps are taken: at most count steps.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private StepOutcome QuietSteps(double step, FlightEventKinds stopAt, int count, out int quiet, out double lastStart)
        {
            FlightState a, b, c;
            StateDerivative ka, kb, kc;
            int taken = 0;
            lastStart = _now.State.Time;
            StepOutcome outcome;
            // From the current state into a (no quiet step before it, so its start is not read), then from a into b.
            if (QuietStep(_now.State, _now.Derivative, _now.State, _now.Derivative, out a, out ka, ref taken, count, step, stopAt, ref lastStart, out outcome) ||
                QuietStep(_now.State, _now.Derivative, a, ka, out b, out kb, ref taken, count, step, stopAt, ref lastStart, out outcome))
            {
                quiet = taken;
                return outcome;
            }

            while (!QuietStep(a, ka, b, kb, out c, out kc, ref taken, count, step, stopAt, ref lastStart, out outcome) &&
                !QuietStep(b, kb, c, kc, out a, out ka, ref taken, count, step, stopAt, ref lastStart, out outcome) &&
                !QuietStep(c, kc, a, ka, out b, out kb, ref taken, count, step, stopAt, ref lastStart, out outcome))
            {
            }

            quiet = taken;
            return outcome;
        }

        // One turn of QuietSteps after `taken` quiet steps, the last from (start, startDerivative) to (end, endDerivative): true,
        // with the call's outcome, where the call ends here (count steps taken: they are committed; or the next step, integrated
        // into (next, nextDerivative), is not quiet: the quiet steps are committed and that step taken as TryStep takes it);
        // false where the next step was quiet (taken counts it). next is not meaningful where it returns true before integrating.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private bool QuietStep(
            in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative,
            out FlightState next, out StateDerivative nextDerivative, ref int taken, int count, double step, FlightEventKinds stopAt,
            ref double lastStart, out StepOutcome outcome)
        {
            if (taken == count)
            {
                CommitQuiet(start, startDerivative, end, endDerivative, taken);
                next = default;
                nextDerivative = default;
                outcome = StepOutcome.Taken;
                return true;
            }

            lastStart = end.Time;
            FixedStepKind kind = IntegrateFixed(end, endDerivative, step, out next, out nextDerivative, out int evaluations);
            if (kind != FixedStepKind.Quiet)
            {
                outcome = AfterQuiet(start, startDerivative, end, endDerivative, taken, next, nextDerivative, kind, step, stopAt, evaluations);
                return true;
            }

            taken++;
            outcome = StepOutcome.Taken;
            return false;
        }

        // QuietSteps after `quiet` quiet steps, the last from (start, startDerivative) to (end, endDerivative) (neither read when
        // quiet is 0), whose next step, integrated into (next, nextDerivative), was not quiet: commits the quiet steps, then takes
        // that step from the first-piece fields as TryStep takes it.
        private StepOutcome AfterQuiet(
            in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative, int quiet,
            in FlightState next, in StateDerivative nextDerivative, FixedStepKind kind, double step, FlightEventKinds stopAt, int evaluations)
        {
            if (quiet > 0)
            {
                CommitQuiet(start, startDerivative, end, endDerivative, quiet);
            }

            _firstPiece = next;
            _firstPieceDerivative = nextDerivative;
            return Finish(kind, step, stopAt, evaluations);
        }

        // The full scan of a plain step's segment, for the steps SurelyClear cannot decide (out of line: the segment is 304 bytes
        // the common step need not build).
        [MethodImpl(MethodImplOptions.NoInlining)]
        private bool ScansClear(in FlightState next, in StateDerivative nextDerivative)
        {
            var segment = new HermiteSegment(_now.State, _now.Derivative, next, nextDerivative, trusted: true);
            return EventSet!.Scan(ref segment, _scratch, _now.StartsFlight, landings: true) == 0;
        }

        // Commits a step of one piece with no event: what Advance does for it, without the snapshot and the piece loop.
        private void TakePlainStep(in FlightState next, in StateDerivative nextDerivative, int evaluations) =>
            Commit(_now.State, _now.Derivative, next, nextDerivative, 1, evaluations);

        // Commits `steps` quiet steps (QuietSteps: RK4's evaluations each).
        private void CommitQuiet(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative, int steps) =>
            Commit(start, startDerivative, end, endDerivative, steps, (long)RungeKutta4.Evaluations * steps);

        // Commits `steps` steps of one piece with no event that made `evaluations` in all, the last from (start, startDerivative)
        // to (end, endDerivative): TakePlainStep's commit of each, at once. start may be the current state (it is read before it
        // is written); end may not be, and neither may be the previous state.
        private void Commit(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative, int steps, long evaluations)
        {
            _now.Previous = start;
            _now.PreviousDerivative = startDerivative;
            _now.State = end;
            _now.Derivative = endDerivative;
            _now.Evaluations += evaluations;
            _now.Steps += steps;
            _now.StartsFlight = false;
            _eventCount = 0;
            _segmentCount = 0;
            _implicitSegment = true;
        }

        /// <summary>
        /// Sets the size of the next adaptive step, in place of <see cref="DormandPrince54.InitialStep"/>'s estimate (and its
        /// evaluation) after <see cref="Reset"/>: the aim solver's trials start with the step an earlier trial's controller
        /// asked for at its launch. Ignored unless finite and &gt; 0; the step is still capped by each call's maximum.
        /// </summary>
        internal void SetNextAdaptiveStep(double step)
        {
            if (step > 0 && step <= double.MaxValue)
            {
                _now.NextAdaptiveStep = step;
            }
        }

        /// <summary>The last adaptive step attempted (its size, error norm and whether it was accepted).</summary>
        internal ref readonly DormandPrince54Step LastAdaptiveStep => ref _adaptiveStep;

        /// <summary>
        /// One adaptive Dormand-Prince 5(4) step of at most <paramref name="maxStep"/> seconds, its size chosen by
        /// error control (the controller's next step is kept between calls); events are located on the method's own
        /// fourth-order interpolant. Allocates nothing.
        /// </summary>
        /// <param name="method">The adaptive method and its tolerances.</param>
        /// <param name="maxStep">The longest step to take, s; finite and &gt; 0 (pass the time left to hit an end time).</param>
        /// <param name="stopAt">The event kinds that end the flight.</param>
        /// <returns>What happened, as for <see cref="TryStep"/>.</returns>
        /// <exception cref="InvalidOperationException">No state was given yet.</exception>
        /// <exception cref="ArgumentException">method is null or maxStep is not finite and positive.</exception>
        public StepOutcome TryStepAdaptive(DormandPrince54 method, double maxStep, FlightEventKinds stopAt = FlightEventKinds.None)
        {
            RequireStarted();
            Require.NotNull(method, nameof(method));
            Require.Step(maxStep, nameof(maxStep));
            return Advance(maxStep, stopAt, method);
        }

        /// <summary>The first event of one of the <paramref name="kinds"/> in the last step.</summary>
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
        /// The step to take toward <paramref name="endTime"/> with steps of <paramref name="step"/>: the step, or the
        /// time left when that is no more than a step (and a part in 1e9): the one end-time rule every client uses, so
        /// a run ends on its end time without a sliver of a step.
        /// </summary>
        /// <param name="now">The current time, s.</param>
        /// <param name="endTime">The end time, s.</param>
        /// <param name="step">The fixed step, s.</param>
        /// <param name="last">True when the returned step reaches the end time.</param>
        /// <exception cref="ArgumentException">A time is not finite, or the step is not finite and &gt; 0; the message names it.</exception>
        public static double StepToward(double now, double endTime, double step, out bool last)
        {
            Require.Finite(now, nameof(now));
            Require.Finite(endTime, nameof(endTime));
            Require.Step(step, nameof(step));
            return StepTowardUnchecked(now, endTime, step, out last);
        }

        /// <summary><see cref="StepToward"/> for loops that checked their step and times once, before the loop.</summary>
        internal static double StepTowardUnchecked(double now, double endTime, double step, out bool last)
        {
            double remaining = endTime - now;
            last = remaining <= step * (1 + 1e-9);
            return last ? remaining : step;
        }

        /// <summary>
        /// The state at <paramref name="time"/> inside the last step, on its dense output (pieces between bounces,
        /// the roll); the step's start before it, the current state after it.
        /// </summary>
        /// <param name="time">The time, s; finite.</param>
        /// <exception cref="ArgumentException">The time is not finite; the message names it.</exception>
        public FlightState StateAt(double time)
        {
            Require.Finite(time, nameof(time));
            if ((_segmentCount == 0 && !_implicitSegment) || time >= _now.State.Time)
            {
                return _now.State;
            }

            if (time <= _now.Previous.Time)
            {
                return _now.Previous;
            }

            if (_implicitSegment)
            {
                return LastSegment.StateAt(time);
            }

            for (int i = 0; i < _segmentCount; i++)
            {
                HermiteSegment segment = _segments[i];
                if (time <= segment.EndTime)
                {
                    return time < segment.StartTime ? segment.Start : segment.StateAt(time);
                }
            }

            return _now.State;
        }

        private StepOutcome Advance(double step, FlightEventKinds stopAt, DormandPrince54? adaptive)
        {
            if (_now.Phase == FlightPhase.Stopped)
            {
                _eventCount = 0;
                return StepOutcome.AlreadyStopped;
            }

            double endTime = _now.State.Time + step;
            if (!(endTime > _now.State.Time))
            {
                return StepOutcome.TimeCannotAdvance;
            }

            // Everything this step may change, kept so that a refused step puts it all back (events and pieces go to the
            // pending arrays, swapped in only when the step is taken). In a field, not a local: Mono zero-fills every struct
            // local on entry (344 bytes here, on every step).
            ref Snapshot before = ref _before;
            before = _now;
            _now.Previous = _now.State;
            _now.PreviousDerivative = _now.Derivative;
            _pendingEventCount = 0;
            _pendingSegmentCount = 0;
            _pendingImplicit = false;

            try
            {
                // Pieces of flight between bounces; bounded by MaxPiecesPerStep. The first piece takes the step as given.
                for (int piece = 0; piece < MaxPiecesPerStep && _now.Phase == FlightPhase.Flying; piece++)
                {
                    double h = piece == 0 ? step : endTime - _now.State.Time;
                    if (!(_now.State.Time + h > _now.State.Time))
                    {
                        break; // less than one ulp of time left after a bounce
                    }

                    bool ok = adaptive == null
                        ? FlyPiece(h, endTime, piece, stopAt)
                        : FlyAdaptivePiece(adaptive, h, piece, stopAt, ref endTime);
                    if (!ok)
                    {
                        _now = before;
                        return _refusal;
                    }

                    if (_now.State.Time >= endTime)
                    {
                        break;
                    }
                }

                if ((_now.Phase == FlightPhase.Rolling && !Roll(endTime)) || !_now.State.IsFinite)
                {
                    // The roll would leave the state or its derivative non-finite (forces beyond double on the surface), or a
                    // bounce in the last ulp of the step left a non-finite state: refused, as a diverging integrator step is.
                    _now = before;
                    return StepOutcome.Diverged;
                }
            }
            catch
            {
                // A user's law, wind profile or bounce model threw inside the step: the step is not taken, nothing changes
                // (the events and pieces written so far are in the pending arrays only).
                _now = before;
                _hasFirstPiece = false;
                throw;
            }

            _now.Steps++;
            _now.StartsFlight = false;
            if (_now.Phase == FlightPhase.Stopped)
            {
                _stopEvent = _pendingStop;
            }

            // The pending arrays become the current ones only when the step wrote into them: with nothing written the
            // current count is zero and which array holds nothing does not matter (and no reference is stored).
            if (_pendingEventCount > 0)
            {
                (_events, _pendingEvents) = (_pendingEvents, _events);
            }

            if (_pendingSegmentCount > 0)
            {
                (_segments, _pendingSegments) = (_pendingSegments, _segments);
            }

            _eventCount = _pendingEventCount;
            _segmentCount = _pendingSegmentCount;
            _implicitSegment = _pendingImplicit;
            return _now.Phase == FlightPhase.Stopped ? StepOutcome.Stopped : StepOutcome.Taken;
        }

        /// <summary>
        /// The one divergence policy: a step from <paramref name="start"/> is taken only when its end state and end
        /// derivative are finite and its clock advanced; otherwise it is refused and nothing changes. Shared with the
        /// ball batch.
        /// </summary>
        internal static bool Takes(in FlightState start, in FlightState end, in StateDerivative endDerivative) =>
            end.IsFinite && endDerivative.IsFinite && end.Time > start.Time;

        // One piece of a fixed step: integrate to endTime, then handle the first event with an effect.
        private bool FlyPiece(double h, double endTime, int piece, FlightEventKinds stopAt)
        {
            FlightState next;
            StateDerivative nextDerivative;
            int evaluations;
            if (piece == 0 && _hasFirstPiece)
            {
                // TryStep integrated this piece already (and found an event in it).
                next = _firstPiece;
                nextDerivative = _firstPieceDerivative;
                evaluations = _firstPieceEvaluations;
                _hasFirstPiece = false;
            }
            else
            {
                next = Integrator.Step(Model, _now.State, _now.Derivative, h, out nextDerivative, out evaluations);
            }

            _refusal = StepOutcome.Diverged;
            if (!Takes(_now.State, next, nextDerivative))
            {
                return false;
            }

            _now.Evaluations += evaluations;
            if (next.Time != endTime)
            {
                // A piece after a bounce: end exactly on the step's end time.
                next = new FlightState(next.Position, next.Velocity, next.AngularVelocity, endTime);
            }

            var segment = new HermiteSegment(_now.State, _now.Derivative, next, nextDerivative, trusted: true);
            return HandlePiece(ref segment, segment, next, nextDerivative, piece, stopAt, implicitPiece: piece == 0);
        }

        // One adaptive step (error control, bounded retries); the step's end time becomes the accepted step's end. Not
        // inlined into Advance: its large locals (the step's dense output) would grow every Advance frame, fixed steps too.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private bool FlyAdaptivePiece(DormandPrince54 method, double h, int piece, FlightEventKinds stopAt, ref double endTime)
        {
            double trial = _now.NextAdaptiveStep > 0 ? Math.Min(_now.NextAdaptiveStep, h) : method.InitialStep(Model, _now.State, _now.Derivative, h);
            if (_now.NextAdaptiveStep <= 0)
            {
                _now.Evaluations++; // InitialStep's one evaluation
            }

            // At most MaxAdaptiveAttempts attempts; after the last one, or once the next step cannot advance the clock, the
            // last attempt is taken as it is.
            // The step is written in place into the stepper's own (no copies of its stages or dense output).
            ref DormandPrince54Step result = ref _adaptiveStep;
            bool accepted = method.TryStepInPlace(Model, _now.State, _now.Derivative, trial, ref result);
            _now.Evaluations += 6;
            for (int attempt = 1;
                 !accepted && attempt < MaxAdaptiveAttempts && result.NextStep > 0 && _now.State.Time + result.NextStep > _now.State.Time;
                 attempt++)
            {
                trial = Math.Min(result.NextStep, h);
                accepted = method.TryStepInPlace(Model, _now.State, _now.Derivative, trial, ref result);
                _now.Evaluations += 6;
            }

            ref readonly FlightState end = ref result.Stages.End;
            ref readonly StateDerivative endDerivative = ref result.Stages.K7;
            _refusal = StepOutcome.Diverged;
            if (!Takes(_now.State, end, endDerivative))
            {
                // Not finite: diverged. Finite, but the accepted step is below the resolution of the time (a huge time, a
                // tiny step): the clock cannot advance.
                _refusal = end.IsFinite && endDerivative.IsFinite ? StepOutcome.TimeCannotAdvance : StepOutcome.Diverged;
                return false;
            }

            _now.NextAdaptiveStep = result.NextStep;
            endTime = end.Time;
            if ((EventSet == null || result.StaysClearOf(EventSet, landings: Contact == null)) &&
                (Contact == null || result.StaysClearOf(_contactPlane, CrossingDirection.AgainstNormal)))
            {
                // Provably no event and no contact in the step (most steps of a flight): what HandlePiece does when its scans
                // find nothing, without them. The step's first piece runs from (Previous, PreviousDerivative) to its end, so
                // its cubic Hermite for StateAt is the implicit one, built only when asked for; a later piece's is stored.
                if (piece == 0)
                {
                    _pendingImplicit = true;
                    _now.State = end;
                    _now.Derivative = endDerivative;
                }
                else
                {
                    ContinueAdaptive(ref result);
                }

                return true;
            }

            return HandleAdaptivePiece(ref result, piece, stopAt);
        }

        // FlyAdaptivePiece's paths that build the step's 304-byte Hermite segment, out of line: Mono zero-fills a method's
        // struct locals on entry, so in FlyAdaptivePiece they cost that on every step, the common one that needs none too.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private void ContinueAdaptive(ref DormandPrince54Step result)
        {
            ref readonly FlightState end = ref result.Stages.End;
            ref readonly StateDerivative endDerivative = ref result.Stages.K7;
            Continue(HermiteSegment.OfTakenStep(result.Start, result.StartDerivative, end, endDerivative), end, endDerivative, implicitPiece: false);
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private bool HandleAdaptivePiece(ref DormandPrince54Step result, int piece, FlightEventKinds stopAt)
        {
            ref readonly FlightState end = ref result.Stages.End;
            ref readonly StateDerivative endDerivative = ref result.Stages.K7;
            // For StateAt between frames: the cubic Hermite through the step's ends (no evaluation).
            var hermite = HermiteSegment.OfTakenStep(result.Start, result.StartDerivative, end, endDerivative);
            return HandlePiece(ref result, hermite, end, endDerivative, piece, stopAt, implicitPiece: false);
        }

        // Locates the piece's events on its dense output, writes those that happen, and applies the first one with an
        // effect (a stop or a bounce); with none, the piece's end becomes the current state. `hermite` is the piece's cubic
        // Hermite, kept for StateAt. False (the step is refused) when the dense output overflows at an event: an extreme but
        // finite step whose interpolant is not finite between its ends. implicitPiece: the piece is the step's first, from
        // (Previous, PreviousDerivative), so a piece with no effect need not be stored (_implicitSegment).
        private bool HandlePiece<TDense>(
            ref TDense dense, in HermiteSegment hermite, in FlightState end, in StateDerivative endDerivative, int piece, FlightEventKinds stopAt,
            bool implicitPiece)
            where TDense : struct, IDenseOutput
        {
            int count = EventSet == null ? 0 : EventSet.Scan(ref dense, _scratch, _now.StartsFlight && piece == 0, landings: Contact == null);
            if (count == 0 && Contact == null)
            {
                // The common piece: no event, no surface to touch. Its end becomes the current state.
                Continue(hermite, end, endDerivative, implicitPiece);
                return true;
            }

            return HandleEvents(ref dense, hermite, end, endDerivative, piece, stopAt, implicitPiece, count);
        }

        // The piece has no effect: its end is the current state, its dense output the step's (implicit) or stored.
        private void Continue(in HermiteSegment hermite, in FlightState end, in StateDerivative endDerivative, bool implicitPiece)
        {
            if (implicitPiece)
            {
                _pendingImplicit = true; // the step is this one piece: (Previous, PreviousDerivative) to (end, endDerivative)
            }
            else
            {
                PushSegment(hermite);
            }

            _now.State = end;
            _now.Derivative = endDerivative;
        }

        // HandlePiece with events found (count of them in _scratch) or a contact surface: out of line, so the common
        // piece's frame holds none of the event copies and spans this needs (they are zeroed on every call).
        [MethodImpl(MethodImplOptions.NoInlining)]
        private bool HandleEvents<TDense>(
            ref TDense dense, in HermiteSegment hermite, in FlightState end, in StateDerivative endDerivative, int piece, FlightEventKinds stopAt,
            bool implicitPiece, int count)
            where TDense : struct, IDenseOutput
        {
            Span<FlightEvent> found = _scratch;
            for (int i = 0; i < count; i++)
            {
                if (!found[i].State.IsFinite)
                {
                    return false;
                }
            }

            double contactTime = double.PositiveInfinity;
            // The last piece a step may hold ignores the contact (MaxPiecesPerStep bounds the work of one step).
            if (Contact != null && piece < MaxPiecesPerStep - 1 &&
                dense.TryFindCrossing(_contactPlane, CrossingDirection.AgainstNormal, false, out double t))
            {
                contactTime = t;
            }

            // Only what comes before the contact happens; of that, the first stop event ends the flight (with the events
            // up to it and at its instant: FlightEventSet.CountUntil, the one rule); otherwise the contact bounces the ball.
            int before = 0;
            while (before < count && found[before].Time <= contactTime)
            {
                before++;
            }

            int happen = FlightEventSet.CountUntil(found.Slice(0, before), stopAt, out int stopIndex);
            if (stopIndex >= 0)
            {
                FlightEvent stop = found[stopIndex];
                if (!hermite.TryUntil(stop.Time, out HermiteSegment cut))
                {
                    return false;
                }

                Record(found.Slice(0, happen));
                PushSegment(cut);
                // The flight is over: its last derivative is the dense output's slope at the stop (no evaluation).
                Stop(stop, cut.Duration > 0 ? cut.EndDerivative : _now.Derivative);
                return true;
            }

            count = before;
            Record(found.Slice(0, count));
            if (double.IsPositiveInfinity(contactTime))
            {
                Continue(hermite, end, endDerivative, implicitPiece);
                return true;
            }

            return Bounce(ref dense, hermite, contactTime, piece);
        }

        private bool Bounce<TDense>(ref TDense dense, in HermiteSegment hermite, double contactTime, int piece)
            where TDense : struct, IDenseOutput
        {
            GroundContact contact = Contact!;
            FlightState touching = dense.StateAt(contactTime);
            Vector3d centre = _contactPlane.Project(touching.Position);
            if (!touching.IsFinite || !centre.IsFinite || !hermite.TryUntil(contactTime, out HermiteSegment cut))
            {
                return false;
            }

            BounceOutcome outcome = contact.Bounce.Bounce(Model.Ball, _normal, touching.Velocity, touching.AngularVelocity);
            if (!outcome.Velocity.IsFinite || !outcome.AngularVelocity.IsFinite)
            {
                return false; // the bounce law overflowed on an extreme impact
            }

            PushSegment(cut);
            double outgoingNormalSpeed = Vector3d.Dot(outcome.Velocity, _normal);
            // Rest only where gravity holds the ball on the surface (a floor or a slope, not a wall or a ceiling).
            bool roll = _gravityHolds &&
                (outcome.Regime == BounceRegime.None || outgoingNormalSpeed < contact.RestNormalSpeed || piece >= MaxPiecesPerStep - 2);
            _now.Bounces++;
            var arriving = new FlightState(centre, touching.Velocity, touching.AngularVelocity, contactTime);
            var leaving = new FlightState(centre, outcome.Velocity, outcome.AngularVelocity, contactTime);
            Write(new FlightEvent(FlightEventKinds.Bounce, -1, arriving, leaving, outcome.Regime, roll));
            if (roll)
            {
                StartRolling(centre, outcome.Velocity, outcome.AngularVelocity, contactTime);
                return true;
            }

            _now.State = leaving;
            _now.Derivative = Model.Derivative(leaving);
            _now.Evaluations++;
            return true;
        }

        private void Stop(in FlightEvent stop, in StateDerivative slope)
        {
            _now.State = stop.State;
            _now.Derivative = slope;
            _now.Phase = FlightPhase.Stopped;
            _pendingStop = stop;
        }

        private void StartRolling(in Vector3d centre, in Vector3d velocity, in Vector3d angularVelocity, double time)
        {
            // Keep the angular momentum about the contact point: roll at Lam / (1 + alpha), Lam = vt - alpha R (n x w).
            double radius = Model.Ball.Radius, alpha = Model.Ball.InertiaFactor;
            Vector3d vt = velocity - _normal * Vector3d.Dot(velocity, _normal);
            Vector3d lambda = vt - Vector3d.Cross(_normal, angularVelocity) * (radius * alpha);
            Vector3d rolling = lambda / (1 + alpha);
            Vector3d spinNormal = _normal * Vector3d.Dot(angularVelocity, _normal);
            _now.Phase = FlightPhase.Rolling;
            var state = new FlightState(centre, rolling, RollingSpin(rolling, spinNormal), time);
            _now.State = state;
            _now.Derivative = new StateDerivative(state.Velocity, RollingAcceleration(state), Vector3d.Zero);
        }

        // The roll to endTime: Heun's method (exact for a constant acceleration, so exact on level ground in still air),
        // with the stop located inside the step where the speed along the motion reaches zero. False, with nothing
        // committed to the segments, when a state or derivative of the roll would not be finite (the caller refuses the step).
        private bool Roll(double endTime)
        {
            if (!(_now.State.Time < endTime))
            {
                return true;
            }

            double h = endTime - _now.State.Time;
            FlightState s0 = _now.State;
            Vector3d v0 = s0.Velocity;
            Vector3d spinNormal = _normal * Vector3d.Dot(s0.AngularVelocity, _normal);
            Vector3d a0 = _now.Derivative.Acceleration;
            if (!s0.IsFinite || !_now.Derivative.IsFinite)
            {
                return false;
            }

            Vector3d vPredicted = v0 + a0 * h;
            if (_canRest && (v0.LengthSquared == 0 || Vector3d.Dot(vPredicted, v0) <= 0))
            {
                return StopWithin(s0, a0, vPredicted, h, spinNormal);
            }

            var predicted = new FlightState(s0.Position + v0 * h, vPredicted, RollingSpin(vPredicted, spinNormal), endTime);
            if (!predicted.IsFinite)
            {
                return false;
            }

            Vector3d a1 = RollingAcceleration(predicted);
            Vector3d average = (a0 + a1) * 0.5;
            Vector3d v1 = v0 + average * h;
            if (_canRest && Vector3d.Dot(v1, v0) <= 0)
            {
                return StopWithin(s0, average, v1, h, spinNormal);
            }

            var next = new FlightState(_contactPlane.Project(s0.Position + (v0 + v1) * (0.5 * h)), v1, RollingSpin(v1, spinNormal), endTime);
            if (!next.IsFinite)
            {
                return false;
            }

            var nextDerivative = new StateDerivative(v1, RollingAcceleration(next), Vector3d.Zero);
            if (!nextDerivative.IsFinite)
            {
                return false;
            }

            PushSegment(new HermiteSegment(s0, _now.Derivative, next, nextDerivative));
            _now.State = next;
            _now.Derivative = nextDerivative;
            return true;
        }

        private bool StopWithin(in FlightState s0, in Vector3d a, in Vector3d v1, double h, in Vector3d spinNormal)
        {
            Vector3d v0 = s0.Velocity;
            double speed = v0.Length;
            double along = speed > 0 ? Vector3d.Dot(v1, v0) / speed : 0;
            double stopAfter = speed > 0 ? h * speed / (speed - along) : 0;
            Vector3d position = _contactPlane.Project(s0.Position + v0 * stopAfter + a * (0.5 * stopAfter * stopAfter));
            var rest = new FlightState(position, Vector3d.Zero, spinNormal, s0.Time + stopAfter);
            var restDerivative = new StateDerivative(Vector3d.Zero, a, Vector3d.Zero);
            if (!rest.IsFinite || !restDerivative.IsFinite || !(stopAfter >= 0))
            {
                return false;
            }

            if (rest.Time > s0.Time)
            {
                PushSegment(new HermiteSegment(s0, _now.Derivative, rest, restDerivative));
            }

            var stop = new FlightEvent(FlightEventKinds.Rest, -1, rest);
            Write(stop);
            _now.State = rest;
            _now.Derivative = default;
            _now.Phase = FlightPhase.Stopped;
            _pendingStop = stop;
            return true;
        }

        private Vector3d RollingAcceleration(in FlightState state)
        {
            Vector3d a = Model.Gravity;
            if (Model.HasAerodynamics)
            {
                a = Model.Derivative(state).Acceleration;
                _now.Evaluations++;
            }

            Vector3d tangential = a - _normal * Vector3d.Dot(a, _normal);
            return tangential * (1.0 / (1 + Model.Ball.InertiaFactor)) - state.Velocity.NormalizedOrZero() * _rollingDeceleration;
        }

        private Vector3d RollingSpin(in Vector3d velocity, in Vector3d spinNormal) =>
            Vector3d.Cross(_normal, velocity) * (1.0 / Model.Ball.Radius) + spinNormal;

        private void Record(Span<FlightEvent> events)
        {
            for (int i = 0; i < events.Length; i++)
            {
                Write(events[i]);
            }
        }

        private void Write(in FlightEvent e)
        {
            // The array holds every event MaxPiecesPerStep pieces can produce; this guard only keeps it in bounds.
            if (_pendingEventCount < _pendingEvents.Length)
            {
                _pendingEvents[_pendingEventCount++] = e;
            }
        }

        private void PushSegment(in HermiteSegment segment)
        {
            if (_pendingSegmentCount < _pendingSegments.Length && segment.Duration > 0)
            {
                _pendingSegments[_pendingSegmentCount++] = segment;
            }
        }

        private void RequireStarted()
        {
            if (!_started)
            {
                throw new InvalidOperationException("Call Reset(state) before stepping.");
            }
        }

        // The mutable state of the flight, one value so that a refused step restores it in one assignment (the stop event
        // and the pieces are outside it: a step changes them only when it is taken).
        private struct Snapshot
        {
            public FlightState State;
            public StateDerivative Derivative;
            public FlightState Previous;
            public StateDerivative PreviousDerivative;
            public FlightPhase Phase;
            public long Steps;
            public long Evaluations;
            public int Bounces;
            public bool StartsFlight;
            public double NextAdaptiveStep;
        }
    }
}
