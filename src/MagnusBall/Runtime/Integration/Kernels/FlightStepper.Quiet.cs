// FlightStepper, part (a fast form: it lives with the others in Integration/Kernels, in its class's namespace, the flight
// layer): the quiet run (TrySteps), several common steps in one call, each handing its end to the next in
// three rotating slots and committed together; the first step that is not quiet is finished as TryStep's common step
// (Finish, in FlightStepper.cs). The main path is TryStep in FlightStepper.cs.
using System;
using System.Runtime.CompilerServices;
using MagnusBall.Integration;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
        /// <summary>
        /// Up to <paramref name="count"/> steps of <paramref name="step"/> seconds in one call (<c>FixedStepDriver</c>'s
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
        internal bool StepsQuietly => Contact == null && _shapes == null && _now.Phase == FlightPhase.Flying && (_plainRk4 || _stableRk4 != null);

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

        // Commits `steps` quiet steps (QuietSteps: RK4's evaluations each).
        private void CommitQuiet(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative, int steps) =>
            Commit(start, startDerivative, end, endDerivative, steps, (long)RungeKutta4.Evaluations * steps);
    }
}
