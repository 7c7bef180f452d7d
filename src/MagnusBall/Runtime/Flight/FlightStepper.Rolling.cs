// FlightStepper, part: rolling on a surface: the ground (the GroundContact) or a contact shape the ball settled on (rolled on the
// shape's tangent plane at the touch). StartRolling and StartRollingOnShape set the surface (in the snapshot, so a refused step puts
// it back); RollPiece takes one step of the rolling ball (Integration/RollingHeun) under slope, rolling resistance and the air, and
// cuts it where something happens first: a shape it rolls into (answered as in flight), the edge where it leaves the shape it
// rolls on (it flies from there), or the stop where it comes to rest (StopWithin). Reached from the general step (Advance,
// FlightStepper.Pieces.cs); the main path is TryStep in FlightStepper.cs.
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Integration;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
        /// <summary>
        /// A ball rolling on a shape has left it where the gap between its surface and the shape exceeds this, m (a box's face
        /// keeps the gap at rounding level; past an edge, or along a curved shape, it grows).
        /// </summary>
        internal const double LeaveGapM = 1e-7;

        // Rolls on the ground (the GroundContact's plane of centres).
        private void StartRolling(in Vector3d centre, in Vector3d velocity, in Vector3d angularVelocity, double time) =>
            StartRollingOn(-1, _contactPlane, _rollingDeceleration, _canRest, centre, velocity, angularVelocity, time);

        // Rolls on shape `index`, on the plane through the ball's centre at the touch normal to the shape there. Its rolling
        // resistance is the ground's coefficient (GroundContact.DefaultRollingResistance without a ground) times gravity into it.
        private void StartRollingOnShape(int index, in FlightState touching, in Vector3d normal)
        {
            bool canRest = RollingLimits(Model, normal, Contact?.RollingResistance ?? GroundContact.DefaultRollingResistance, out double deceleration);
            StartRollingOn(
                index, new Plane(touching.Position, normal), deceleration, canRest, touching.Position, touching.Velocity, touching.AngularVelocity,
                touching.Time);
        }

        // The rolling resistance's deceleration on a surface of unit normal `normal` (coefficient times gravity into it), and
        // whether the slope alone cannot keep the ball moving against it (so it can come to rest).
        private static bool RollingLimits(FlightModel model, in Vector3d normal, double coefficient, out double deceleration)
        {
            double gn = -Vector3d.Dot(model.Gravity, normal);
            Vector3d gt = model.Gravity + normal * gn;
            deceleration = coefficient * System.Math.Max(gn, 0);
            return gt.Length / (1 + model.Ball.InertiaFactor) <= deceleration;
        }

        // Rolls on `plane` from here; with a `wall` (a shape's index and its normal), pressed against that shape and rolling
        // along it: its roll's velocity into the wall is taken away and the wall holds it (RollingAcceleration). The wall is kept
        // by its normal's part in the plane (InPlane), which is what it takes away, as the plane is fixed while the ball rolls.
        private void StartRollingOn(
            int shape, in Plane plane, double deceleration, bool canRest, in Vector3d centre, in Vector3d velocity, in Vector3d angularVelocity,
            double time, int wall = -1, in Vector3d wallNormal = default)
        {
            _now.RollShape = shape;
            _now.RollPlane = plane;
            _now.RollDeceleration = deceleration;
            _now.RollCanRest = canRest;
            Vector3d normal = plane.Normal;
            Vector3d wallInPlane = InPlane(wallNormal, normal);
            _now.RollWall = wall;
            _now.RollWallNormal = wallInPlane;
            // Keep the angular momentum about the contact point: roll at Lam / (1 + alpha), Lam = vt - alpha R (n x w).
            double radius = Model.Ball.Radius, alpha = Model.Ball.InertiaFactor;
            Vector3d vt = velocity - normal * Vector3d.Dot(velocity, normal);
            Vector3d lambda = vt - Vector3d.Cross(normal, angularVelocity) * (radius * alpha);
            Vector3d rolling = lambda / (1 + alpha);
            double intoWall = Vector3d.Dot(rolling, wallInPlane);
            if (intoWall < 0)
            {
                rolling -= wallInPlane * intoWall;
            }
            Vector3d spinNormal = normal * Vector3d.Dot(angularVelocity, normal);
            _now.Phase = FlightPhase.Rolling;
            var state = new FlightState(centre, rolling, RollingSpin(rolling, spinNormal), time);
            _now.State = state;
            _now.Derivative = new StateDerivative(state.Velocity, RollingAcceleration(state), Vector3d.Zero);
        }

        // One piece of the roll toward endTime: one step of RollingHeun (exact for a constant acceleration, so exact on level ground
        // in still air), with the stop located inside it where the speed along the motion reaches zero; cut at the first shape it
        // touches or the edge where it leaves the shape it rolls on. False, with nothing committed to the segments, when a state or
        // derivative of the roll would not be finite (the caller refuses the step).
        private bool RollPiece(double endTime, int piece, FlightEventKinds stopAt)
        {
            if (!(_now.State.Time < endTime))
            {
                return true;
            }

            double h = endTime - _now.State.Time;
            FlightState s0 = _now.State;
            Vector3d v0 = s0.Velocity;
            Vector3d normal = _now.RollPlane.Normal;
            Vector3d spinNormal = normal * Vector3d.Dot(s0.AngularVelocity, normal);
            Vector3d a0 = _now.Derivative.Acceleration;
            if (!s0.IsFinite || !_now.Derivative.IsFinite)
            {
                return false;
            }

            FlightState end;
            StateDerivative endDerivative;
            bool rests;
            RollingHeun.Predict(s0.Position, v0, a0, h, out Vector3d pPredicted, out Vector3d vPredicted);
            if (_now.RollCanRest && (v0.LengthSquared == 0 || Vector3d.Dot(vPredicted, v0) <= 0))
            {
                rests = true;
                RestWithin(s0, a0, vPredicted, h, spinNormal, out end, out endDerivative);
            }
            else
            {
                var predicted = new FlightState(pPredicted, vPredicted, RollingSpin(vPredicted, spinNormal), endTime);
                if (!predicted.IsFinite)
                {
                    return false;
                }

                Vector3d a1 = RollingAcceleration(predicted);
                RollingHeun.Correct(s0.Position, v0, a0, a1, h, out Vector3d average, out Vector3d p1, out Vector3d v1);
                if (_now.RollCanRest && Vector3d.Dot(v1, v0) <= 0)
                {
                    rests = true;
                    RestWithin(s0, average, v1, h, spinNormal, out end, out endDerivative);
                }
                else
                {
                    rests = false;
                    end = new FlightState(_now.RollPlane.Project(p1), v1, RollingSpin(v1, spinNormal), endTime);
                    endDerivative = end.IsFinite ? new StateDerivative(v1, RollingAcceleration(end), Vector3d.Zero) : default;
                }
            }

            if (!end.IsFinite || !endDerivative.IsFinite || !(end.Time >= s0.Time))
            {
                return false;
            }

            if (_now.RollWall >= 0 && !rests)
            {
                KeepAlongTheWall(ref end, ref endDerivative);
            }

            // On a shape: where the rolled end is off the shape's surface (a curved shape, or past an edge), the ball stays on it
            // while the shape falls away no faster than the ball falls (its free path from the piece's start ends on or in the
            // shape): it is put back on the surface and rolls on from its tangent plane there; otherwise it leaves the shape
            // within the piece (HandleEvents locates where).
            Vector3d reanchor = Vector3d.Zero;
            bool mayLeave = false;
            if (_now.RollShape >= 0 && !rests && end.Time > s0.Time)
            {
                ContactShape rolledOn = _shapes![_now.RollShape];
                double radius = Model.Ball.Radius;
                double gap = rolledOn.SignedDistance(end.Position, out Vector3d surfaceNormal) - radius;
                bool stays = gap < -LeaveGapM;
                if (gap > LeaveGapM)
                {
                    Vector3d free = s0.Position + v0 * h + FlightKernel.DerivativeOf(Model, s0).Acceleration * (0.5 * h * h);
                    _now.Evaluations++;
                    stays = !(rolledOn.SignedDistance(free, out _) - radius > 0);
                    mayLeave = !stays;
                }

                if (stays && Vector3d.Dot(Model.Gravity, surfaceNormal) < 0)
                {
                    double off = Vector3d.Dot(end.Velocity, surfaceNormal);
                    end = new FlightState(end.Position - surfaceNormal * gap, end.Velocity - surfaceNormal * off, end.AngularVelocity, end.Time);
                    endDerivative = new StateDerivative(end.Velocity, endDerivative.Acceleration, Vector3d.Zero);
                    reanchor = surfaceNormal;
                }
                else if (stays)
                {
                    mayLeave = true; // gravity no longer holds it there (past the side of a ring): it leaves
                }
            }

            if (end.Time > s0.Time && (_shapes != null || EventSet != null || (Contact != null && _now.RollShape >= 0)))
            {
                // The piece is searched as a piece of flight is: the events on it, the shapes it meets, the ground under a ball
                // rolling on a shape, the edge where it leaves its shape; the first cut wins (HandleEvents, FlightStepper.Pieces.cs).
                var segment = new HermiteSegment(s0, _now.Derivative, end, endDerivative);
                int count = EventSet == null ? 0 : EventSet.Scan(ref segment, _scratch, false, landings: Contact == null);
                if (!HandleEvents(ref segment, segment, end, endDerivative, piece, stopAt, implicitPiece: false, count, rests, mayLeave))
                {
                    return false;
                }

                if (reanchor.LengthSquared > 0 && _now.Phase == FlightPhase.Rolling && _now.State.Time == end.Time)
                {
                    // Nothing cut the piece: the ball rolls on from the surface's tangent plane at its end.
                    StartRollingOnShape(_now.RollShape, _now.State, reanchor);
                }

                return _now.State.IsFinite;
            }

            if (end.Time > s0.Time)
            {
                PushSegment(new HermiteSegment(s0, _now.Derivative, end, endDerivative));
            }

            _now.State = end;
            _now.Derivative = endDerivative;
            if (rests)
            {
                Rest(end);
            }

            return true;
        }

        // A ball rolling along a wall (RollWall): its velocity into the wall is taken away at the piece's end; where the wall no
        // longer holds it (the wall ends, or the slope no longer presses the ball into it) it rolls free from the next piece.
        private void KeepAlongTheWall(ref FlightState end, ref StateDerivative endDerivative)
        {
            Vector3d wallInPlane = _now.RollWallNormal;
            double into = Vector3d.Dot(end.Velocity, wallInPlane);
            if (into < 0)
            {
                end = new FlightState(end.Position, end.Velocity - wallInPlane * into, end.AngularVelocity, end.Time);
                endDerivative = new StateDerivative(end.Velocity, endDerivative.Acceleration, Vector3d.Zero);
            }

            Vector3d normal = _now.RollPlane.Normal;
            Vector3d g = Model.Gravity - normal * Vector3d.Dot(Model.Gravity, normal);
            double gap = _shapes![_now.RollWall].SignedDistance(end.Position, out _) - Model.Ball.Radius;
            if (gap > LeaveGapM || Vector3d.Dot(g, wallInPlane) >= 0)
            {
                _now.RollWall = -1;
            }
        }

        // Where the rolling ball stops inside the step: its velocity along the motion reaches zero after `stopAfter`.
        private void RestWithin(in FlightState s0, in Vector3d a, in Vector3d v1, double h, in Vector3d spinNormal,
            out FlightState rest, out StateDerivative restDerivative)
        {
            Vector3d v0 = s0.Velocity;
            double speed = v0.Length;
            double along = speed > 0 ? Vector3d.Dot(v1, v0) / speed : 0;
            double stopAfter = speed > 0 ? h * speed / (speed - along) : 0;
            Vector3d position = _now.RollPlane.Project(s0.Position + v0 * stopAfter + a * (0.5 * stopAfter * stopAfter));
            rest = new FlightState(position, Vector3d.Zero, spinNormal, s0.Time + stopAfter);
            restDerivative = new StateDerivative(Vector3d.Zero, a, Vector3d.Zero);
        }

        // The flight is over: the ball rests at `rest`.
        private void Rest(in FlightState rest)
        {
            var stop = new FlightEvent(FlightEventKinds.Rest, -1, rest);
            Write(stop);
            _now.State = rest;
            _now.Derivative = default;
            _now.Phase = FlightPhase.Stopped;
            _pendingStop = stop;
        }

        // The first time on the rolling piece at which the ball's gap to the shape it rolls on exceeds LeaveGapM (bisection to the
        // events' time tolerance; the gap only grows once the ball is past the edge), or +infinity when it stays on to the end.
        private double LeaveTime(in HermiteSegment segment)
        {
            ContactShape shape = _shapes![_now.RollShape];
            double radius = Model.Ball.Radius;
            if (!(shape.SignedDistance(segment.End.Position, out _) - radius > LeaveGapM))
            {
                return segment.EndTime; // it leaves by the piece's end (gravity no longer holds it on the shape)
            }

            double lo = segment.StartTime, hi = segment.EndTime;
            for (int i = 0; i < 64 && hi - lo > HermiteSegment.TimeTolerance; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (shape.SignedDistance(segment.StateAt(mid).Position, out _) - radius > LeaveGapM)
                {
                    hi = mid;
                }
                else
                {
                    lo = mid;
                }
            }

            return hi;
        }

        // Over the edge of the shape it rolls on at `time`: it flies from there.
        private bool LeaveShape(in HermiteSegment segment, double time)
        {
            if (!segment.TryUntil(time, out HermiteSegment cut))
            {
                return false;
            }

            PushSegment(cut);
            FlyFrom(segment.StateAt(time));
            return _now.State.IsFinite;
        }

        // The rolling ball touches shape `index` at `time`: the shape answers it (Contact.Impact); it rolls on from there on the same
        // surface, or flies where the answer sends it off the surface faster than the rest speed. A slow touch into a shape that the
        // rolling ball is pressed against (a wall at the foot of a slope) rests it against the shape, or, moving along the shape,
        // rolls it on along it.
        private bool RollContact(in HermiteSegment segment, double time, int index, in Vector3d normal, FlightEventKinds stopAt)
        {
            ContactShape shape = _shapes![index];
            if (!CutAt(segment, time, out FlightState touching, out HermiteSegment cut))
            {
                return false;
            }

            touching = new FlightState(_now.RollPlane.Project(touching.Position), touching.Velocity, touching.AngularVelocity, time);
            double restSpeed = Contact?.RestNormalSpeed ?? GroundContact.DefaultRestNormalSpeed;
            double approach = -Vector3d.Dot(touching.Velocity, normal);
            Vector3d pressed = RollingAcceleration(touching);
            if (approach < restSpeed && Vector3d.Dot(pressed, normal) < 0 && (stopAt & FlightEventKinds.Contact) == 0)
            {
                // Pressed slowly into the shape (a wall at the foot of a slope): it rests against it, or, moving along it faster than
                // the rest speed, rolls on along it (the wall holds it: its acceleration into the wall is taken away).
                Vector3d along = touching.Velocity + normal * approach;
                Vector3d surfaceNormal = _now.RollPlane.Normal;
                if (along.Length < restSpeed)
                {
                    var against = new FlightState(touching.Position, Vector3d.Zero, surfaceNormal * Vector3d.Dot(touching.AngularVelocity, surfaceNormal), time);
                    Write(new FlightEvent(shape.Id, touching, against, BounceRegime.None, normal, startsRolling: false));
                    Rest(against);
                    return true;
                }

                StartRollingOn(
                    _now.RollShape, _now.RollPlane, _now.RollDeceleration, _now.RollCanRest, touching.Position, along, touching.AngularVelocity, time,
                    wall: index, wallNormal: normal);
                Write(new FlightEvent(shape.Id, touching, _now.State, BounceRegime.None, normal, startsRolling: false));
                return _now.State.IsFinite && _now.Derivative.IsFinite;
            }

            if (!Answer(shape, touching, normal, cut, stopAt, out FlightState leaving))
            {
                return false;
            }

            if (_now.Phase == FlightPhase.Stopped)
            {
                return true;
            }

            if (Vector3d.Dot(leaving.Velocity, _now.RollPlane.Normal) > restSpeed)
            {
                FlyFrom(leaving);
                return true;
            }

            StartRollingOn(
                _now.RollShape, _now.RollPlane, _now.RollDeceleration, _now.RollCanRest, touching.Position, leaving.Velocity, leaving.AngularVelocity, time);
            return _now.State.IsFinite && _now.Derivative.IsFinite;
        }

        private Vector3d RollingAcceleration(in FlightState state)
        {
            Vector3d a = Model.Gravity;
            if (Model.HasAerodynamics)
            {
                a = FlightKernel.DerivativeOf(Model, state).Acceleration;
                _now.Evaluations++;
            }

            Vector3d normal = _now.RollPlane.Normal;
            Vector3d tangential = a - normal * Vector3d.Dot(a, normal);
            if (_now.RollWall >= 0)
            {
                double intoWall = Vector3d.Dot(tangential, _now.RollWallNormal);
                if (intoWall < 0)
                {
                    tangential -= _now.RollWallNormal * intoWall; // the wall holds the ball
                }
            }

            return tangential * (1.0 / (1 + Model.Ball.InertiaFactor)) - state.Velocity.NormalizedOrZero() * _now.RollDeceleration;
        }

        // A wall's normal as the rolling ball meets it: its part in the plane it rolls on, as a unit vector. The ball moves in that
        // plane, so what the wall takes away is its motion along this direction; taking away the motion along the wall's own normal
        // where the wall leans over the plane would leave the ball a part of it into the wall (the plane's projection turns the part
        // off the plane into the wall), and it would sink into a leaning wall as it rolled along it.
        private static Vector3d InPlane(in Vector3d wallNormal, in Vector3d planeNormal) =>
            (wallNormal - planeNormal * Vector3d.Dot(wallNormal, planeNormal)).NormalizedOrZero();

        private Vector3d RollingSpin(in Vector3d velocity, in Vector3d spinNormal) =>
            Vector3d.Cross(_now.RollPlane.Normal, velocity) * (1.0 / Model.Ball.Radius) + spinNormal;
    }
}
