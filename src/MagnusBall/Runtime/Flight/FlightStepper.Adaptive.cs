// FlightStepper, part: the adaptive step (TryStepAdaptive): one Dormand-Prince 5(4) piece at a time, retried at a smaller
// size while the error control rejects it (FlyAdaptivePiece), its events located on the method's own interpolant. The
// piece loop it runs in is Advance (FlightStepper.Pieces.cs); the main path is TryStep in FlightStepper.cs.
using System;
using System.Runtime.CompilerServices;
using MagnusBall.Integration;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
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
            if (_shapes == null && (EventSet == null || StaysClearOf(result, EventSet, landings: Contact == null)) &&
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

        /// <summary>
        /// True when the adaptive step provably holds none of the events <paramref name="events"/> watches, with the landing
        /// on its ground only when <paramref name="landings"/> (as FlightEventSet.Scan): its scan would find nothing. The
        /// bounds are the step's (DormandPrince54Step.StaysClearOf, StaysClearOfApex); which events to ask about is the
        /// flight's, so it lives here and the integration layer knows no events.
        /// </summary>
        private static bool StaysClearOf(in DormandPrince54Step step, FlightEventSet events, bool landings)
        {
            Plane? ground = landings ? events.Ground : null;
            if (ground.HasValue && !step.StaysClearOf(ground.Value, CrossingDirection.AgainstNormal))
            {
                return false;
            }

            Vector3d up = events.Up;
            if (up.LengthSquared > 0 && !step.StaysClearOfApex(up))
            {
                return false;
            }

            Plane[] planes = events.PlaneArray;
            for (int i = 0; i < planes.Length; i++)
            {
                if (!step.StaysClearOf(planes[i], CrossingDirection.AlongNormal))
                {
                    return false;
                }
            }

            return true;
        }
    }
}
