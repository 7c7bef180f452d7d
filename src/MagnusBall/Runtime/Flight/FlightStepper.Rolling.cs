// FlightStepper, part: rolling on a contact surface (StartRolling, Roll): steps of the rolling ball (Integration/RollingHeun) under slope,
// rolling resistance and the air, and the stop where it comes to rest (StopWithin). Reached from the general step
// (Advance, FlightStepper.Pieces.cs); the main path is TryStep in FlightStepper.cs.
using MagnusBall.Integration;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
        private void StartRolling(in Vector3d centre, in Vector3d velocity, in Vector3d angularVelocity, double time)
        {
            // Keep the angular momentum about the contact point: roll at Lam / (1 + alpha), Lam = vt - alpha R (n x w).
            double radius = Model.Ball.Radius, alpha = Model.Ball.InertiaFactor;
            Vector3d vt = velocity - _normal * Vector3d.Dot(velocity, _normal);
            Vector3d lambda = vt - Vector3d.Cross(_normal, angularVelocity) * (radius * alpha);
            Vector3d rolling = lambda / (1 + alpha);
            Vector3d spinNormal = _normal * Vector3d.Dot(angularVelocity, _normal);
            _now.Phase = FlightPhase.Rolling;
            var state = new FlightState(centre, rolling, RollingSpin(rolling, spinNormal), time);
            _now.State = state;
            _now.Derivative = new StateDerivative(state.Velocity, RollingAcceleration(state), Vector3d.Zero);
        }

        // The roll to endTime: one step of RollingHeun (exact for a constant acceleration, so exact on level ground in still air),
        // with the stop located inside the step where the speed along the motion reaches zero. False, with nothing
        // committed to the segments, when a state or derivative of the roll would not be finite (the caller refuses the step).
        private bool Roll(double endTime)
        {
            if (!(_now.State.Time < endTime))
            {
                return true;
            }

            double h = endTime - _now.State.Time;
            FlightState s0 = _now.State;
            Vector3d v0 = s0.Velocity;
            Vector3d spinNormal = _normal * Vector3d.Dot(s0.AngularVelocity, _normal);
            Vector3d a0 = _now.Derivative.Acceleration;
            if (!s0.IsFinite || !_now.Derivative.IsFinite)
            {
                return false;
            }

            RollingHeun.Predict(s0.Position, v0, a0, h, out Vector3d pPredicted, out Vector3d vPredicted);
            if (_canRest && (v0.LengthSquared == 0 || Vector3d.Dot(vPredicted, v0) <= 0))
            {
                return StopWithin(s0, a0, vPredicted, h, spinNormal);
            }

            var predicted = new FlightState(pPredicted, vPredicted, RollingSpin(vPredicted, spinNormal), endTime);
            if (!predicted.IsFinite)
            {
                return false;
            }

            Vector3d a1 = RollingAcceleration(predicted);
            RollingHeun.Correct(s0.Position, v0, a0, a1, h, out Vector3d average, out Vector3d p1, out Vector3d v1);
            if (_canRest && Vector3d.Dot(v1, v0) <= 0)
            {
                return StopWithin(s0, average, v1, h, spinNormal);
            }

            var next = new FlightState(_contactPlane.Project(p1), v1, RollingSpin(v1, spinNormal), endTime);
            if (!next.IsFinite)
            {
                return false;
            }

            var nextDerivative = new StateDerivative(v1, RollingAcceleration(next), Vector3d.Zero);
            if (!nextDerivative.IsFinite)
            {
                return false;
            }

            PushSegment(new HermiteSegment(s0, _now.Derivative, next, nextDerivative));
            _now.State = next;
            _now.Derivative = nextDerivative;
            return true;
        }

        private bool StopWithin(in FlightState s0, in Vector3d a, in Vector3d v1, double h, in Vector3d spinNormal)
        {
            Vector3d v0 = s0.Velocity;
            double speed = v0.Length;
            double along = speed > 0 ? Vector3d.Dot(v1, v0) / speed : 0;
            double stopAfter = speed > 0 ? h * speed / (speed - along) : 0;
            Vector3d position = _contactPlane.Project(s0.Position + v0 * stopAfter + a * (0.5 * stopAfter * stopAfter));
            var rest = new FlightState(position, Vector3d.Zero, spinNormal, s0.Time + stopAfter);
            var restDerivative = new StateDerivative(Vector3d.Zero, a, Vector3d.Zero);
            if (!rest.IsFinite || !restDerivative.IsFinite || !(stopAfter >= 0))
            {
                return false;
            }

            if (rest.Time > s0.Time)
            {
                PushSegment(new HermiteSegment(s0, _now.Derivative, rest, restDerivative));
            }

            var stop = new FlightEvent(FlightEventKinds.Rest, -1, rest);
            Write(stop);
            _now.State = rest;
            _now.Derivative = default;
            _now.Phase = FlightPhase.Stopped;
            _pendingStop = stop;
            return true;
        }

        private Vector3d RollingAcceleration(in FlightState state)
        {
            Vector3d a = Model.Gravity;
            if (Model.HasAerodynamics)
            {
                a = FlightKernel.DerivativeOf(Model, state).Acceleration;
                _now.Evaluations++;
            }

            Vector3d tangential = a - _normal * Vector3d.Dot(a, _normal);
            return tangential * (1.0 / (1 + Model.Ball.InertiaFactor)) - state.Velocity.NormalizedOrZero() * _rollingDeceleration;
        }

        private Vector3d RollingSpin(in Vector3d velocity, in Vector3d spinNormal) =>
            Vector3d.Cross(_normal, velocity) * (1.0 / Model.Ball.Radius) + spinNormal;
    }
}
