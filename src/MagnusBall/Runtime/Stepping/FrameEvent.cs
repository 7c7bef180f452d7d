using MagnusBall.Contact;
using MagnusBall.Queries;

namespace MagnusBall.Stepping
{
    /// <summary>What happened at a <see cref="FrameEvent"/>.</summary>
    public enum FrameEventKind
    {
        /// <summary>The ball came down on the ground plane and, without a bounce model, the flight ended there.</summary>
        Landing = 0,

        /// <summary>The ball's centre crossed one of the watched planes along the plane's normal (a net, a line, a wall).</summary>
        PlaneCrossing = 1,

        /// <summary>The top of the flight: the velocity along up changed sign.</summary>
        Apex = 2,

        /// <summary>The ball bounced off the court (only with a bounce model); it flies on, or rolls if <see cref="FrameEvent.StartsRolling"/>.</summary>
        Bounce = 3,

        /// <summary>The ball stopped rolling: the flight has ended (only with a bounce model).</summary>
        Stop = 4,
    }

    /// <summary>
    /// Something that happened while <see cref="FixedStepDriver.Advance(double, System.Span{FrameEvent})"/>
    /// consumed a frame, located inside its fixed step on the step's cubic Hermite (to 1e-12 s, see
    /// <see cref="HermiteSegment"/>), not rounded to a step: the exact simulation time and state there.
    /// </summary>
    /// <remarks>
    /// The driver draws one fixed step behind the simulation, so an event found in this frame's steps may
    /// lie after <see cref="FixedStepDriver.RenderTime"/>: compare <see cref="Time"/> with it to know when
    /// the player sees it.
    /// </remarks>
    public readonly struct FrameEvent
    {
        /// <summary>What happened.</summary>
        public readonly FrameEventKind Kind;

        /// <summary>Index of the crossed plane in the driver's <see cref="FlightEventSet.Planes"/>; -1 for the other kinds.</summary>
        public readonly int PlaneIndex;

        /// <summary>The state at the event (for a bounce: just before it). Its time is the event time, s.</summary>
        public readonly FlightState State;

        /// <summary>For a <see cref="FrameEventKind.Bounce"/>: the state just after the bounce (default otherwise).</summary>
        public readonly FlightState AfterBounce;

        /// <summary>For a bounce: true when it was too weak to leave the court and the ball started rolling.</summary>
        public readonly bool StartsRolling;

        /// <summary>For a bounce: whether the contact point slid or gripped (<see cref="BounceRegime.None"/> otherwise).</summary>
        public readonly BounceRegime Regime;

        /// <summary>Creates an event.</summary>
        /// <param name="kind">What happened.</param>
        /// <param name="planeIndex">Index of the crossed plane, or -1.</param>
        /// <param name="state">The state at the event (before a bounce).</param>
        /// <param name="afterBounce">The state after a bounce (default otherwise).</param>
        /// <param name="regime">The bounce regime (None otherwise).</param>
        /// <param name="startsRolling">For a bounce: whether the ball started rolling.</param>
        public FrameEvent(
            FrameEventKind kind, int planeIndex, in FlightState state, in FlightState afterBounce = default, BounceRegime regime = BounceRegime.None,
            bool startsRolling = false)
        {
            StartsRolling = startsRolling;
            Kind = kind;
            PlaneIndex = planeIndex;
            State = state;
            AfterBounce = afterBounce;
            Regime = regime;
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
        /// <summary>Fixed steps taken in this call (a last step cut short by a landing counts as one).</summary>
        public readonly int StepsTaken;

        /// <summary>Events written to the caller's buffer, in time order.</summary>
        public readonly int EventCount;

        /// <summary>Events that happened but did not fit in the caller's buffer (they are lost; pass a larger buffer).</summary>
        public readonly int EventsNotReported;

        /// <summary>
        /// Frame time, s, that was not simulated: the part of a hitch above the clamp, what was left when the
        /// substep cap was reached, and all frame time once the flight has ended. The ball runs this much
        /// behind the wall clock; its path is unchanged.
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
