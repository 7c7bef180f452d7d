using System;
using System.Runtime.CompilerServices;
using MagnusBall.Contact;
using MagnusBall.Integration;

namespace MagnusBall.Flight
{
    /// <summary>What happened at a <see cref="FlightEvent"/>. Flags, so a set of kinds can say where to stop.</summary>
    [Flags]
    public enum FlightEventKinds
    {
        /// <summary>No event.</summary>
        None = 0,

        /// <summary>The ball crossed the ground plane against its normal (from above).</summary>
        Landing = 1,

        /// <summary>The ball crossed one of the watched planes along its normal (a net, a goal line, a wall).</summary>
        PlaneCrossing = 2,

        /// <summary>The velocity along up (-gravity) changed from positive to zero or below: the top of the flight.</summary>
        Apex = 4,

        /// <summary>
        /// The ball touched the contact surface and bounced (a flight with a <see cref="GroundContact"/>):
        /// <see cref="FlightEvent.State"/> is the ball arriving, <see cref="FlightEvent.After"/> leaving.
        /// </summary>
        Bounce = 8,

        /// <summary>The rolling ball came to rest (a flight with a <see cref="GroundContact"/>).</summary>
        Rest = 16,

        /// <summary>
        /// The ball touched one of the flight's contact shapes (<see cref="MagnusBall.Contact.Shapes.ContactShape"/>) and was
        /// answered by it: <see cref="FlightEvent.ShapeId"/> names the shape, <see cref="FlightEvent.ContactNormal"/> is its outward
        /// normal at the contact, <see cref="FlightEvent.State"/> the ball arriving and <see cref="FlightEvent.After"/> leaving.
        /// A slow touch that the ball's weight holds it in settles it on the shape (<see cref="FlightEvent.StartsRolling"/>): it rolls
        /// on from there. A stop kind (stopAt) that names Contact ends the flight at the touch, with the ball arriving.
        /// </summary>
        Contact = 32,

        /// <summary>Every kind.</summary>
        All = Landing | PlaneCrossing | Apex | Bounce | Rest | Contact,
    }

    /// <summary>
    /// Something that happened inside a step, located on the step's dense output: its kind, the plane it concerns
    /// (for plane crossings), the state at that instant and, for a bounce, the state leaving the surface. The one
    /// event type of the library: the flight core, the predictor, the aim solvers and the fixed-step driver all
    /// report these.
    /// </summary>
    public readonly struct FlightEvent
    {
        /// <summary>What happened (exactly one flag).</summary>
        public readonly FlightEventKinds Kind;

        /// <summary>
        /// For <see cref="FlightEventKinds.PlaneCrossing"/>, the index of the plane in the watched list; for a
        /// <see cref="FlightEventKinds.Contact"/>, the shape's id (<see cref="ShapeId"/>); otherwise -1.
        /// </summary>
        public readonly int PlaneIndex;

        /// <summary>The interpolated state at the event (time to 1e-12 s); for a bounce, the ball arriving.</summary>
        public readonly FlightState State;

        /// <summary>For a bounce, the state leaving the surface (same time and position); otherwise the same as <see cref="State"/>.</summary>
        public readonly FlightState After;

        /// <summary>For a bounce, how it went (slide or grip); otherwise <see cref="BounceRegime.None"/>.</summary>
        public readonly BounceRegime Regime;

        /// <summary>
        /// For a bounce, true when the ball left the surface too slowly to fly and rolls from here; for a contact, true when the
        /// ball settled on the shape (it arrived too slowly to bounce, held there by its weight) and rolls on it from here.
        /// </summary>
        public readonly bool StartsRolling;

        /// <summary>
        /// For a <see cref="FlightEventKinds.Contact"/>, the shape's unit outward normal at the contact (from the shape toward the
        /// ball's centre; the contact point is <see cref="Position"/> minus the ball's radius times it); for a
        /// <see cref="FlightEventKinds.Bounce"/>, the ground's normal, the same way; otherwise zero.
        /// </summary>
        public readonly Vector3d ContactNormal;

        /// <summary>Creates an event with no bounce data.</summary>
        /// <param name="kind">What happened.</param>
        /// <param name="planeIndex">Index of the crossed plane, or -1.</param>
        /// <param name="state">The state at the event.</param>
        internal FlightEvent(FlightEventKinds kind, int planeIndex, in FlightState state)
            : this(kind, planeIndex, state, state, BounceRegime.None, false)
        {
        }

        /// <summary>Creates an event.</summary>
        /// <param name="kind">What happened.</param>
        /// <param name="planeIndex">Index of the crossed plane, or -1.</param>
        /// <param name="state">The state at the event (for a bounce, arriving).</param>
        /// <param name="after">The state just after it (for a bounce, leaving).</param>
        /// <param name="regime">For a bounce, its regime.</param>
        /// <param name="startsRolling">For a bounce, whether the ball rolls from here.</param>
        /// <param name="normal">For a bounce, the ground's unit normal; otherwise zero.</param>
        internal FlightEvent(
            FlightEventKinds kind, int planeIndex, in FlightState state, in FlightState after, BounceRegime regime, bool startsRolling,
            in Vector3d normal = default)
        {
            Kind = kind;
            PlaneIndex = planeIndex;
            State = state;
            After = after;
            Regime = regime;
            StartsRolling = startsRolling;
            ContactNormal = normal;
        }

        /// <summary>Creates a contact event: the shape's id (kept where a crossing keeps its plane's index) and normal.</summary>
        internal FlightEvent(int shapeId, in FlightState state, in FlightState after, BounceRegime regime, in Vector3d normal, bool startsRolling)
        {
            Kind = FlightEventKinds.Contact;
            PlaneIndex = shapeId;
            State = state;
            After = after;
            Regime = regime;
            StartsRolling = startsRolling;
            ContactNormal = normal;
        }

        /// <summary>For a <see cref="FlightEventKinds.Contact"/>, the id the caller gave the shape hit; otherwise -1.</summary>
        public int ShapeId => Kind == FlightEventKinds.Contact ? PlaneIndex : -1;

        /// <summary>Time of the event, s.</summary>
        public double Time => State.Time;

        /// <summary>Position at the event, m.</summary>
        public Vector3d Position => State.Position;

        /// <summary>Velocity at the event (for a bounce, arriving), m/s.</summary>
        public Vector3d Velocity => State.Velocity;

        /// <inheritdoc />
        public override string ToString() =>
            Kind == FlightEventKinds.PlaneCrossing ? $"{Kind}[{PlaneIndex}] {State}"
            : Kind == FlightEventKinds.Contact ? $"{Kind}[{PlaneIndex}] ({Regime}) n={ContactNormal} {State} -> v={After.Velocity} w={After.AngularVelocity}"
            : Kind == FlightEventKinds.Bounce ? $"{Kind} ({Regime}{(StartsRolling ? ", rolls" : string.Empty)}) {State} -> v={After.Velocity} w={After.AngularVelocity}"
            : $"{Kind} {State}";
    }

    /// <summary>
    /// Which events to look for in a step: the ground (landing), the apex and any number of planes.
    /// Immutable; build it once (it copies the plane list) and reuse it every step.
    /// </summary>
    public sealed class FlightEventSet
    {
        private readonly Plane[] _planes;
        private readonly bool _hasGround, _hasUp; // the same tests Scan makes, kept for SurelyClear
        private readonly Plane _groundValue;

        /// <summary>Creates an event set.</summary>
        /// <param name="up">The up direction for the apex (for example <see cref="FlightModel.Up"/>); finite. Zero switches the apex off.</param>
        /// <param name="ground">The ground plane for landings, or null for none.</param>
        /// <param name="planes">Planes whose crossings along their normal are reported (copied), or null for none.</param>
        /// <exception cref="ArgumentException">up is not finite, or a plane has a zero normal.</exception>
        public FlightEventSet(Vector3d up, Plane? ground = null, Plane[]? planes = null)
        {
            Require.Finite(up, nameof(up));
            Up = up.NormalizedOrZero();
            if (ground.HasValue && ground.Value.Normal.LengthSquared == 0)
            {
                throw new ArgumentException("ground must have a non-zero normal (use new Plane(point, normal) or Plane.Ground(model)).", nameof(ground));
            }

            Ground = ground;
            _hasGround = ground.HasValue;
            _groundValue = ground.GetValueOrDefault();
            _hasUp = Up.LengthSquared > 0;
            _planes = planes == null ? Array.Empty<Plane>() : (Plane[])planes.Clone();
            for (int i = 0; i < _planes.Length; i++)
            {
                if (_planes[i].Normal.LengthSquared == 0)
                {
                    throw new ArgumentException($"planes[{i}] must have a non-zero normal.", nameof(planes));
                }
            }
        }

        /// <summary>
        /// An event set with no apex that watches <paramref name="ground"/> and the planes in <paramref name="planes"/>,
        /// sharing the caller's array instead of copying it: the aim solver sets each trial's plane in it. Internal:
        /// every public set is immutable.
        /// </summary>
        internal static FlightEventSet Sharing(Plane ground, Plane[] planes) => new FlightEventSet(ground, planes);

        private FlightEventSet(Plane ground, Plane[] planes)
        {
            Up = Vector3d.Zero;
            Ground = ground;
            _hasGround = true;
            _groundValue = ground;
            _planes = planes;
        }

        /// <summary>The events a flight model usually needs: landing on <see cref="Plane.Ground(FlightModel, Vector3d)"/> through the origin, the apex, and the given planes.</summary>
        /// <param name="model">The flight model (its gravity must be non-zero).</param>
        /// <param name="planes">Planes to watch, or null.</param>
        public static FlightEventSet ForModel(FlightModel model, params Plane[]? planes) =>
            new FlightEventSet(Require.NotNull(model, nameof(model)).Up, Plane.Ground(model), planes);

        /// <summary>The unit up direction used for the apex (zero: no apex events).</summary>
        internal Vector3d Up { get; }

        /// <summary>The ground plane, or null.</summary>
        public Plane? Ground { get; }

        /// <summary>The watched planes, in the order their <see cref="FlightEvent.PlaneIndex"/> refers to.</summary>
        public ReadOnlySpan<Plane> Planes => _planes;

        /// <summary>The most events one step can report: one landing, one apex and one crossing per plane.</summary>
        internal int MaximumEventsPerStep => 2 + _planes.Length;

        /// <summary>The planes watched (the set's own array: read only).</summary>
        internal Plane[] PlaneArray => _planes;

        /// <summary>
        /// Finds the events inside one step and writes them to <paramref name="events"/> in time order: the
        /// first landing, the first apex and the first crossing of each plane inside (StartTime, EndTime] (for
        /// the first step of a flight, a landing or crossing at StartTime too). For tests: it allocates a buffer (the stepper
        /// and the batch call the array overload with their own).
        /// </summary>
        /// <param name="segment">The step's dense output.</param>
        /// <param name="events">Where to write; at least <see cref="MaximumEventsPerStep"/> long.</param>
        /// <param name="startsFlight">
        /// True for the first step of a flight (after a reset or a replaced state): a ball that starts exactly on
        /// the ground or a watched plane and heads through it crosses it at the step's start (see
        /// <see cref="HermiteSegment.TryFindCrossing(in Plane, CrossingDirection, bool, out double)"/>). False (the
        /// default) for a step that continues a flight, whose start was the previous step's end.
        /// </param>
        /// <returns>How many events were written.</returns>
        /// <exception cref="ArgumentException">The buffer is shorter than <see cref="MaximumEventsPerStep"/>.</exception>
        internal int Scan(in HermiteSegment segment, Span<FlightEvent> events, bool startsFlight = false)
        {
            if (events.Length < MaximumEventsPerStep)
            {
                throw new ArgumentException(
                    $"events must hold at least MaximumEventsPerStep = {MaximumEventsPerStep} events; got {events.Length}.", nameof(events));
            }

            HermiteSegment copy = segment;
            var buffer = new FlightEvent[MaximumEventsPerStep]; // this overload is for tests; the stepper passes its own array
            int count = Scan(ref copy, buffer, startsFlight, landings: true);
            buffer.AsSpan(0, count).CopyTo(events);
            return count;
        }

        /// <summary>
        /// True when a Hermite step between these ends surely holds none of this set's events (landing included): the
        /// tests <see cref="Scan{TDense}"/> itself starts each search with, on the same numbers wherever this is true (a
        /// number that is not finite makes it false, and the search forms it again), so when this is true a scan of the
        /// step's segment finds nothing. The flight core asks this before it builds the segment.
        /// </summary>
        internal bool SurelyClear(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative)
        {
            if (_hasGround &&
                !HermiteSegment.SurelyNoCrossing(_groundValue, CrossingDirection.AgainstNormal, start, startDerivative, end, endDerivative))
            {
                return false;
            }

            if (_hasUp && !HermiteSegment.SurelyNoApex(Up, start, startDerivative, end, endDerivative))
            {
                return false;
            }

            Plane[] planes = _planes;
            for (int i = 0; i < planes.Length; i++)
            {
                if (!HermiteSegment.SurelyNoCrossing(planes[i], CrossingDirection.AlongNormal, start, startDerivative, end, endDerivative))
                {
                    return false;
                }
            }

            return true;
        }

        /// <summary>
        /// <see cref="Scan"/> on any dense output (a Hermite segment or an adaptive step's interpolant), with the
        /// landing optional (a flight with a contact surface reports bounces instead). The buffer must hold
        /// <see cref="MaximumEventsPerStep"/> events. An array, not a span: a step with no event (the common case) then
        /// touches neither the buffer nor its length (on 1,000 drivers a cache miss each), and no span is built.
        /// </summary>
        internal int Scan<TDense>(ref TDense dense, FlightEvent[] events, bool startsFlight, bool landings)
            where TDense : struct, IDenseOutput =>
            ScanPlanes(ref dense, Up, landings ? Ground : null, _planes, events, startsFlight);

        /// <summary>
        /// Of one step's events in time order (as <see cref="Scan"/> writes them), how many happen when the flight
        /// ends at the first event of the <paramref name="stopAt"/> kinds (for example the landing): the events up
        /// to and including it, and any at the same instant after it; all of them when none is of those kinds.
        /// The one rule every "fly until it lands" loop uses: crossings before the landing count, nothing after.
        /// </summary>
        /// <param name="events">The step's events, in time order.</param>
        /// <param name="stopAt">The kinds that end the flight (None: nothing does).</param>
        /// <param name="stopIndex">The index of the first event of those kinds, or -1.</param>
        /// <returns>How many of the events, from the first, happen.</returns>
        internal static int CountUntil(Span<FlightEvent> events, FlightEventKinds stopAt, out int stopIndex)
        {
            stopIndex = -1;
            for (int i = 0; i < events.Length; i++)
            {
                if ((events[i].Kind & stopAt) != 0)
                {
                    stopIndex = i;
                    int count = i + 1;
                    while (count < events.Length && events[count].Time <= events[i].Time)
                    {
                        count++;
                    }

                    return count;
                }
            }

            return events.Length;
        }

        /// <summary>
        /// <see cref="Scan"/> for an ad-hoc set (no allocation): the apex along <paramref name="up"/> (unit, or zero
        /// for none), landings on <paramref name="ground"/>, crossings of <paramref name="planes"/>. The buffer must
        /// hold 2 + planes.Length events.
        /// </summary>
        internal static int ScanPlanes<TDense>(
            ref TDense segment, in Vector3d up, Plane? ground, Plane[] planes, FlightEvent[] events, bool startsFlight)
            where TDense : struct, IDenseOutput
        {
            int count = 0;
            double time;
            if (ground.HasValue && segment.TryFindCrossing(ground.Value, CrossingDirection.AgainstNormal, startsFlight, out time))
            {
                count = Found(ref segment, events, count, FlightEventKinds.Landing, -1, time);
            }

            if (up.LengthSquared > 0 && segment.TryFindApex(up, out time))
            {
                count = Found(ref segment, events, count, FlightEventKinds.Apex, -1, time);
            }

            for (int i = 0; i < planes.Length; i++)
            {
                if (segment.TryFindCrossing(planes[i], CrossingDirection.AlongNormal, startsFlight, out time))
                {
                    count = Found(ref segment, events, count, FlightEventKinds.PlaneCrossing, i, time);
                }
            }

            if (count > 1)
            {
                SortByTime(events, count);
            }

            return count;
        }

        // Writes one found event (out of line: the scan of a step with no event, the common case, then carries none of the
        // event's copies in its frame).
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static int Found<TDense>(ref TDense segment, FlightEvent[] events, int count, FlightEventKinds kind, int planeIndex, double time)
            where TDense : struct, IDenseOutput
        {
            events[count] = new FlightEvent(kind, planeIndex, segment.StateAt(time));
            return count + 1;
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private static void SortByTime(FlightEvent[] events, int count)
        {
            // Insertion sort by time (stable: at equal times the landing stays first): a handful of events at most.
            for (int i = 1; i < count; i++)
            {
                FlightEvent e = events[i];
                int j = i - 1;
                while (j >= 0 && events[j].Time > e.Time)
                {
                    events[j + 1] = events[j];
                    j--;
                }

                events[j + 1] = e;
            }
        }
    }
}
