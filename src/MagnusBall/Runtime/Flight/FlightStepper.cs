// FlightStepper, the one stepping loop: its public surface (state, counters, Reset, TryStep) and the common step,
// one piece with no event, taken at once (Steps -> IntegrateFixed -> Finish -> TakePlainStep). The main path starts at TryStep.
// The other concerns, each in its own file: Integration/Kernels/FlightStepper.Quiet.cs (TrySteps' run of quiet steps, a fast form), FlightStepper.Pieces.cs
// (the general step: pieces, events, bounces, stops), FlightStepper.Adaptive.cs (TryStepAdaptive and its retry),
// FlightStepper.Rolling.cs (rolling and coming to rest on a contact surface), FlightStepper.Shapes.cs (contact shapes),
// FlightStepper.Reading.cs (the last step's events, StateAt, StepToward).
using System;
using System.Runtime.CompilerServices;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Integration;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Flight
{
    /// <summary>How a ball moves: flying, rolling on a contact surface, or stopped.</summary>
    public enum FlightPhase
    {
        /// <summary>In the air (free flight under gravity, drag and Magnus).</summary>
        Flying = 0,

        /// <summary>Rolling on the contact surface, or on a contact shape the ball settled on.</summary>
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
    /// <para><b>Bounds.</b> A step holds at most <see cref="MaxPiecesPerStep"/> pieces of flight or roll between bounces and
    /// contacts; a ball bouncing on the ground that late is put to rolling, and a ball that would touch more often than that is
    /// held at its last touch until the step's end. <see cref="TryStepAdaptive"/> retries a rejected adaptive step at
    /// most <see cref="MaxAdaptiveAttempts"/> times. Nothing here loops without a cap.</para>
    /// <para><b>Failure.</b> A refused step (<see cref="StepOutcome.Diverged"/>, <see cref="StepOutcome.TimeCannotAdvance"/>)
    /// and every call that throws leave the stepper exactly as it was.</para>
    /// <para>Not thread-safe: one stepper per ball. The model, integrator, event set and contact it holds are
    /// immutable and may be shared.</para>
    /// </remarks>
    public sealed partial class FlightStepper
    {
        /// <summary>The most pieces of flight or roll (between bounces and contacts) one step holds.</summary>
        internal const int MaxPiecesPerStep = 16;

        /// <summary>The most attempts <see cref="TryStepAdaptive"/> makes before it accepts the smallest step it tried.</summary>
        internal const int MaxAdaptiveAttempts = 64;

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
        /// <param name="shapes">Shapes the ball can hit (walls, posts, the net, a rim: <see cref="ContactShape"/>), copied; or null for none.
        /// Each touch is a <see cref="FlightEventKinds.Contact"/> event and the flight goes on from the shape's answer.</param>
        /// <exception cref="ArgumentNullException">model or integrator is null.</exception>
        /// <exception cref="ArgumentException">An element of shapes is null.</exception>
        public FlightStepper(
            FlightModel model, IIntegrator integrator, FlightEventSet? events = null, GroundContact? contact = null, ContactShape[]? shapes = null)
        {
            if (shapes != null)
            {
                for (int i = 0; i < shapes.Length; i++)
                {
                    if (shapes[i] == null)
                    {
                        throw new ArgumentException($"shapes[{i}] is null; every element must be a shape.", nameof(shapes));
                    }

                    // The impact law takes a body of at least 1e-12 of the ball's mass (Contact.Impact): refused here, not mid-flight.
                    double ballMass = Require.NotNull(model, nameof(model)).Ball.Mass;
                    if (!(shapes[i].EffectiveMassKg >= 1e-12 * ballMass))
                    {
                        throw new ArgumentException(
                            $"shapes[{i}].EffectiveMassKg must be at least 1e-12 of the ball's mass ({Require.Format(1e-12 * ballMass)} kg); " +
                            $"got {Require.Format(shapes[i].EffectiveMassKg)} kg.", nameof(shapes));
                    }
                }

                _shapes = shapes.Length > 0 ? (ContactShape[])shapes.Clone() : null;
            }

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
                _gravityHolds = -Vector3d.Dot(model.Gravity, _normal) > 0;
                _canRest = RollingLimits(model, _normal, contact.RollingResistance, out _rollingDeceleration);
            }
        }

        /// <summary>The flight model.</summary>
        internal FlightModel Model { get; }

        /// <summary>The integration method.</summary>
        internal IIntegrator Integrator { get; }

        /// <summary>The events looked for in each step, or null.</summary>
        internal FlightEventSet? EventSet { get; }

        /// <summary>The surface the ball bounces and rolls on, or null.</summary>
        internal GroundContact? Contact { get; }

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
        internal StateDerivative Derivative => _now.Derivative;

        /// <summary>The state at the start of the last step.</summary>
        internal FlightState PreviousState => _now.Previous;

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
        internal int MaximumEventsPerStep => _events.Length;

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
        internal long StepCount => _now.Steps;

        /// <summary>Bounces since the last <see cref="Reset"/>.</summary>
        public int BounceCount => _now.Bounces;

        /// <summary>Model evaluations since the last <see cref="Reset"/> (including the one at the start state).</summary>
        public long DerivativeEvaluations => _now.Evaluations;

        /// <summary>
        /// The work done since the last <see cref="Reset"/>, as the work caps of the driver and the predictor count it: model
        /// evaluations, plus steps (a step's dense output and event scan cost about one evaluation), plus the pieces of path the
        /// shapes' touch searches looked at (each tests one point against one shape).
        /// </summary>
        internal long Work => _now.Evaluations + _now.Steps + _now.SearchVisits;

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
            StateDerivative derivative = FlightKernel.DerivativeOf(Model, state);
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
        /// <param name="stopAt">The event kinds that end the flight (for example <see cref="FlightEventKinds.Landing"/>;
        /// <see cref="FlightEventKinds.Bounce"/> or <see cref="FlightEventKinds.Contact"/> end it at the touch, the ball arriving);
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
            if (Contact != null || _shapes != null || _now.Phase != FlightPhase.Flying)
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
            public long SearchVisits; // pieces of path the shape searches looked at (ShapeSweep), the rest of a step's work
            public int Bounces;
            public bool StartsFlight;
            public double NextAdaptiveStep;

            // The surface the ball rolls on (Phase Rolling): a shape's index, or -1 for the ground; the plane of its centre there,
            // the rolling resistance's deceleration and whether the slope alone cannot keep it moving.
            public int RollShape;
            public Plane RollPlane;
            public double RollDeceleration;
            public bool RollCanRest;

            // A shape the rolling ball rolls along, pressed against it (a wall at the foot of a slope), -1 for none, and its normal's
            // part in RollPlane, a unit vector (what the wall takes away).
            public int RollWall;
            public Vector3d RollWallNormal;
        }
    }
}
