namespace MagnusBall.Stepping
{
    /// <summary>What happened at a <see cref="FrameEvent"/>.</summary>
    public enum FrameEventKind
    {
        /// <summary>The ball's centre crossed the ground plane from above: the flight ends here (no bounce model).</summary>
        Landing = 0,

        /// <summary>The ball's centre crossed one of the driver's planes along the plane's normal (a net, a line, a wall).</summary>
        PlaneCrossing = 1,

        /// <summary>The ball bounced off the ground and flies on (reserved for a bounce model; see docs/unity.md).</summary>
        Bounce = 2,
    }

    /// <summary>
    /// Something that happened while <see cref="FixedStepDriver.Advance(double, System.Span{FrameEvent})"/>
    /// consumed a frame: a landing or a plane crossing, with the exact simulation time and the state there,
    /// located inside the fixed step in which it happened (not rounded to a step).
    /// </summary>
    /// <remarks>
    /// The driver renders one fixed step behind the simulation (it interpolates between the last two fixed
    /// states), so an event found in this frame's steps may lie slightly after <see cref="FixedStepDriver.RenderTime"/>:
    /// compare <see cref="Time"/> with it to know when the player will see the event.
    /// </remarks>
    public readonly struct FrameEvent
    {
        /// <summary>What happened.</summary>
        public readonly FrameEventKind Kind;

        /// <summary>Index of the crossed plane in the driver's plane list; -1 for a landing or a bounce.</summary>
        public readonly int PlaneIndex;

        /// <summary>The state at the event (its <see cref="FlightState.Time"/> is the event time, s).</summary>
        public readonly FlightState State;

        /// <summary>Creates an event.</summary>
        /// <param name="kind">What happened.</param>
        /// <param name="planeIndex">Index of the crossed plane, or -1.</param>
        /// <param name="state">The state at the event.</param>
        public FrameEvent(FrameEventKind kind, int planeIndex, in FlightState state)
        {
            Kind = kind;
            PlaneIndex = planeIndex;
            State = state;
        }

        /// <summary>The simulation time of the event, s.</summary>
        public double Time => State.Time;

        /// <summary>The position of the ball's centre at the event, m.</summary>
        public Vector3d Position => State.Position;

        /// <inheritdoc />
        public override string ToString() => $"{Kind}{(PlaneIndex >= 0 ? "[" + PlaneIndex + "]" : string.Empty)} at {State}";
    }

    /// <summary>What one call of <see cref="FixedStepDriver.Advance(double, System.Span{FrameEvent})"/> did.</summary>
    public readonly struct AdvanceResult
    {
        /// <summary>Fixed steps taken in this call (a step cut short by a landing counts as one).</summary>
        public readonly int StepsTaken;

        /// <summary>Events written to the caller's buffer, in time order.</summary>
        public readonly int EventCount;

        /// <summary>Events that happened but did not fit in the caller's buffer (they are lost; pass a larger buffer).</summary>
        public readonly int EventsNotReported;

        /// <summary>
        /// Frame time, s, that was not simulated: the part of a hitch above the clamp, and anything left over
        /// when the substep cap was reached. The ball runs this much behind the wall clock; its path is unchanged.
        /// </summary>
        public readonly double DroppedSeconds;

        /// <summary>Creates a result.</summary>
        /// <param name="stepsTaken">Fixed steps taken.</param>
        /// <param name="eventCount">Events written.</param>
        /// <param name="eventsNotReported">Events that did not fit.</param>
        /// <param name="droppedSeconds">Frame time not simulated, s.</param>
        public AdvanceResult(int stepsTaken, int eventCount, int eventsNotReported, double droppedSeconds)
        {
            StepsTaken = stepsTaken;
            EventCount = eventCount;
            EventsNotReported = eventsNotReported;
            DroppedSeconds = droppedSeconds;
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"steps={StepsTaken} events={EventCount} notReported={EventsNotReported} dropped={DroppedSeconds:R} s";
    }
}
