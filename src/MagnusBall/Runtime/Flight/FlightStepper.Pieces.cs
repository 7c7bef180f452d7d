// FlightStepper, part: the general step (Advance), for a step that may hold events or a bounce: a snapshot, then pieces of
// flight (FlyPiece) each scanned for events (HandlePiece, HandleEvents) and cut at the first with an effect (a stop, a
// bounce); the step is committed or the snapshot put back. The main path is TryStep in FlightStepper.cs; the common step
// reaches Advance only where its one piece may hold an event.
using System;
using System.Runtime.CompilerServices;
using MagnusBall.Contact;
using MagnusBall.Integration;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
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
                // Pieces of flight and of rolling, cut at each bounce, contact or edge; bounded by MaxPiecesPerStep. The first piece
                // takes the step as given.
                for (int piece = 0; piece < MaxPiecesPerStep && _now.Phase != FlightPhase.Stopped; piece++)
                {
                    double h = piece == 0 ? step : endTime - _now.State.Time;
                    if (!(_now.State.Time + h > _now.State.Time))
                    {
                        break; // less than one ulp of time left after a bounce
                    }

                    bool ok;
                    if (_now.Phase == FlightPhase.Rolling)
                    {
                        _refusal = StepOutcome.Diverged;
                        ok = RollPiece(endTime, piece, stopAt);
                    }
                    else
                    {
                        ok = adaptive == null
                            ? FlyPiece(h, endTime, piece, stopAt)
                            : FlyAdaptivePiece(adaptive, h, piece, stopAt, ref endTime);
                    }

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

                if (!_now.State.IsFinite || !_now.Derivative.IsFinite)
                {
                    // A bounce in the last ulp of the step left a non-finite state, or a roll begun at an extreme state a non-finite
                    // derivative: refused, as a diverging integrator step is.
                    _now = before;
                    return StepOutcome.Diverged;
                }

                if (_now.Phase != FlightPhase.Stopped && _now.State.Time < endTime)
                {
                    HoldUntil(endTime);
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
            if (count == 0 && Contact == null && _shapes == null)
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
            bool implicitPiece, int count, bool rests = false, bool mayLeave = false)
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

            // A piece of a roll (RollPiece) is searched as a piece of flight is, less the surface it rolls on.
            bool rolling = _now.Phase == FlightPhase.Rolling;
            double contactTime = double.PositiveInfinity;
            if (Contact != null && (!rolling || _now.RollShape >= 0) &&
                dense.TryFindCrossing(_contactPlane, CrossingDirection.AgainstNormal, false, out double t))
            {
                contactTime = t;
            }

            int shapeIndex = -1;
            Vector3d shapeNormal = default;
            if (_shapes != null && FindShapeContact(hermite, out double shapeTime, out shapeIndex, out shapeNormal))
            {
                if (shapeTime < contactTime)
                {
                    contactTime = shapeTime;
                }
                else
                {
                    shapeIndex = -1; // the ground comes first
                }
            }

            // A ball rolling on a shape leaves it over an edge (unless it touches something first).
            bool leaves = false;
            if (mayLeave)
            {
                double leave = LeaveTime(hermite);
                if (leave < contactTime)
                {
                    contactTime = leave;
                    shapeIndex = -1;
                    leaves = true;
                }
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
                if (rests)
                {
                    Rest(end);
                }

                return true;
            }

            if (leaves)
            {
                return LeaveShape(hermite, contactTime);
            }

            if (shapeIndex >= 0)
            {
                return rolling
                    ? RollContact(hermite, contactTime, shapeIndex, shapeNormal, stopAt)
                    : ShapeContact(hermite, contactTime, shapeIndex, shapeNormal, stopAt);
            }

            return Bounce(ref dense, hermite, contactTime, piece, stopAt);
        }

        private bool Bounce<TDense>(ref TDense dense, in HermiteSegment hermite, double contactTime, int piece, FlightEventKinds stopAt)
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
            var bounce = new FlightEvent(FlightEventKinds.Bounce, -1, arriving, leaving, outcome.Regime, roll, _normal);
            Write(bounce);
            if ((stopAt & FlightEventKinds.Bounce) != 0)
            {
                Stop(bounce, cut.Duration > 0 ? cut.EndDerivative : _now.Derivative);
                return true;
            }

            if (roll)
            {
                StartRolling(centre, outcome.Velocity, outcome.AngularVelocity, contactTime);
                return true;
            }

            FlyFrom(leaving); // also a ball that rolled off a shape onto the ground
            return true;
        }

        private void Stop(in FlightEvent stop, in StateDerivative slope)
        {
            _now.State = stop.State;
            _now.Derivative = slope;
            _now.Phase = FlightPhase.Stopped;
            _pendingStop = stop;
        }

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
    }
}
