using System;

namespace MagnusBall.Queries
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

        /// <summary>Every kind.</summary>
        All = Landing | PlaneCrossing | Apex,
    }

    /// <summary>
    /// An event located inside a step on the step's cubic Hermite interpolant: its kind, the plane it
    /// concerns (for plane crossings) and the full interpolated state (time, position, velocity, spin).
    /// </summary>
    public readonly struct FlightEvent
    {
        /// <summary>What happened (exactly one flag).</summary>
        public readonly FlightEventKinds Kind;

        /// <summary>For <see cref="FlightEventKinds.PlaneCrossing"/>, the index of the plane in the watched list; otherwise -1.</summary>
        public readonly int PlaneIndex;

        /// <summary>The interpolated state at the event (time to 1e-12 s).</summary>
        public readonly FlightState State;

        /// <summary>Creates an event.</summary>
        /// <param name="kind">What happened.</param>
        /// <param name="planeIndex">Index of the crossed plane, or -1.</param>
        /// <param name="state">The state at the event.</param>
        public FlightEvent(FlightEventKinds kind, int planeIndex, in FlightState state)
        {
            Kind = kind;
            PlaneIndex = planeIndex;
            State = state;
        }

        /// <summary>Time of the event, s.</summary>
        public double Time => State.Time;

        /// <summary>Position at the event, m.</summary>
        public Vector3d Position => State.Position;

        /// <summary>Velocity at the event, m/s.</summary>
        public Vector3d Velocity => State.Velocity;

        /// <inheritdoc />
        public override string ToString() =>
            Kind == FlightEventKinds.PlaneCrossing ? $"{Kind}[{PlaneIndex}] {State}" : $"{Kind} {State}";
    }

    /// <summary>
    /// Which events to look for in a step: the ground (landing), the apex and any number of planes.
    /// Immutable; build it once (it copies the plane list) and reuse it every step.
    /// </summary>
    public sealed class FlightEventSet
    {
        private readonly Plane[] _planes;

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
            _planes = planes == null ? Array.Empty<Plane>() : (Plane[])planes.Clone();
            for (int i = 0; i < _planes.Length; i++)
            {
                if (_planes[i].Normal.LengthSquared == 0)
                {
                    throw new ArgumentException($"planes[{i}] must have a non-zero normal.", nameof(planes));
                }
            }
        }

        /// <summary>The events a flight model usually needs: landing on <see cref="Plane.Ground(FlightModel, Vector3d)"/> through the origin, the apex, and the given planes.</summary>
        /// <param name="model">The flight model (its gravity must be non-zero).</param>
        /// <param name="planes">Planes to watch, or null.</param>
        public static FlightEventSet ForModel(FlightModel model, params Plane[]? planes) =>
            new FlightEventSet(Require.NotNull(model, nameof(model)).Up, Plane.Ground(model), planes);

        /// <summary>The unit up direction used for the apex (zero: no apex events).</summary>
        public Vector3d Up { get; }

        /// <summary>The ground plane, or null.</summary>
        public Plane? Ground { get; }

        /// <summary>The watched planes, in the order their <see cref="FlightEvent.PlaneIndex"/> refers to.</summary>
        public ReadOnlySpan<Plane> Planes => _planes;

        /// <summary>The most events one step can report: one landing, one apex and one crossing per plane.</summary>
        public int MaximumEventsPerStep => 2 + _planes.Length;

        /// <summary>
        /// Finds the events inside one step and writes them to <paramref name="events"/> in time order: the
        /// first landing, the first apex and the first crossing of each plane inside (StartTime, EndTime] (for
        /// the first step of a flight, a landing or crossing at StartTime too). Allocates nothing.
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
        public int Scan(in HermiteSegment segment, Span<FlightEvent> events, bool startsFlight = false)
        {
            if (events.Length < MaximumEventsPerStep)
            {
                throw new ArgumentException(
                    $"events must hold at least MaximumEventsPerStep = {MaximumEventsPerStep} events; got {events.Length}.", nameof(events));
            }

            return ScanPlanes(segment, Up, Ground, _planes, events, startsFlight);
        }

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
        public static int CountUntil(ReadOnlySpan<FlightEvent> events, FlightEventKinds stopAt, out int stopIndex)
        {
            stopIndex = -1;
            Span<FlightEvent> read = SpanView.Of(events); // not the read-only indexer: Mono 6.8 lacks it (see SpanView)
            for (int i = 0; i < read.Length; i++)
            {
                if ((read[i].Kind & stopAt) != 0)
                {
                    stopIndex = i;
                    int count = i + 1;
                    while (count < read.Length && read[count].Time <= read[i].Time)
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
        internal static int ScanPlanes(
            in HermiteSegment segment, in Vector3d up, Plane? ground, Span<Plane> planes, Span<FlightEvent> events, bool startsFlight)
        {
            int count = 0;
            double time;
            if (ground.HasValue && segment.TryFindCrossing(ground.Value, CrossingDirection.AgainstNormal, startsFlight, out time))
            {
                events[count++] = new FlightEvent(FlightEventKinds.Landing, -1, segment.StateAt(time));
            }

            if (up.LengthSquared > 0 && segment.TryFindApex(up, out time))
            {
                events[count++] = new FlightEvent(FlightEventKinds.Apex, -1, segment.StateAt(time));
            }

            for (int i = 0; i < planes.Length; i++)
            {
                if (segment.TryFindCrossing(planes[i], CrossingDirection.AlongNormal, startsFlight, out time))
                {
                    events[count++] = new FlightEvent(FlightEventKinds.PlaneCrossing, i, segment.StateAt(time));
                }
            }

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

            return count;
        }
    }
}
