using MagnusBall.Flight;

namespace MagnusBall.Stepping
{
    /// <summary>What one call of <see cref="FixedStepDriver.Advance(double, System.Span{FlightEvent})"/> did.</summary>
    public readonly struct AdvanceResult
    {
        /// <summary>Fixed steps taken in this call (a last step cut short by a landing counts as one).</summary>
        public readonly int StepsTaken;

        /// <summary>Events written to the caller's buffer, in time order.</summary>
        public readonly int EventCount;

        /// <summary>
        /// Events that happened but did not fit in the caller's buffer (they are lost). Never more than 0 with a buffer of at
        /// least <see cref="FixedStepDriver.MaximumEventsPerStep"/>: the driver then stops stepping before a step whose events
        /// might not fit (<see cref="StepsDeferred"/>).
        /// </summary>
        public readonly int EventsNotReported;

        /// <summary>
        /// True when the call stopped stepping because the caller's buffer (at least
        /// <see cref="FixedStepDriver.MaximumEventsPerStep"/> long) might not hold the next step's events: the frame time
        /// not yet stepped stays in the driver. Read the events, then call Advance(0, events) again, in the same frame, until this
        /// is false: left to the next frame's call, the ball is drawn behind a driver given a larger buffer (by up to a tenth of
        /// a second in a frame with many bounces) until it catches up. Each call counts its own step and work caps. Never true
        /// for a smaller buffer, whose overflow is counted in EventsNotReported.
        /// </summary>
        public readonly bool StepsDeferred;

        /// <summary>
        /// Frame time, s, that was not simulated: the part of a hitch above the clamp, what was left when the
        /// step cap (MaxStepsPerAdvance) or the work cap (MaxEvaluationsPerAdvance) was reached, and all frame time once the flight has ended. The ball runs this much
        /// behind the wall clock; its path is unchanged.
        /// </summary>
        public readonly double DroppedSeconds;

        /// <summary>
        /// True when a fixed step was refused, its state not finite (diverged) or its clock unable to advance (a start time
        /// near 1e20 s): the driver kept the last finite state and ended the flight (<see cref="FixedStepDriver.Diverged"/>).
        /// </summary>
        public readonly bool Diverged;

        internal AdvanceResult(int stepsTaken, int eventCount, int eventsNotReported, double droppedSeconds, bool diverged, bool stepsDeferred = false)
        {
            StepsDeferred = stepsDeferred;
            Diverged = diverged;
            StepsTaken = stepsTaken;
            EventCount = eventCount;
            EventsNotReported = eventsNotReported;
            DroppedSeconds = droppedSeconds;
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"steps={StepsTaken} events={EventCount} notReported={EventsNotReported} dropped={DroppedSeconds:R} s{(Diverged ? " diverged" : string.Empty)}{(StepsDeferred ? " deferred" : string.Empty)}";
    }
}
