// FlightStepper, part: reading the flight between steps: the last step's events (TryGetEvent), the state at any time
// inside it on its dense output (StateAt), and the one end-time rule (StepToward). The main path is TryStep in FlightStepper.cs.
using System;
using MagnusBall.Integration;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
        /// <summary>The first event of one of the <paramref name="kinds"/> in the last step.</summary>
        /// <param name="kinds">The kinds to look for.</param>
        /// <param name="found">The event; default when none.</param>
        /// <returns>True when one was found.</returns>
        internal bool TryGetEvent(FlightEventKinds kinds, out FlightEvent found)
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

        private void RequireStarted()
        {
            if (!_started)
            {
                throw new InvalidOperationException("Call Reset(state) before stepping.");
            }
        }
    }
}
