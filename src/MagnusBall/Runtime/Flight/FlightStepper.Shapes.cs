// FlightStepper, part: contact shapes (Contact/Shapes). A piece of flight is searched for the first touch of each shape on its
// cubic Hermite (FindShapeContact, through Contact/Shapes/ShapeSweep.cs); a touch becomes a new piece of the step as a ground
// bounce does (HandleEvents in FlightStepper.Pieces.cs takes the earlier of the two), answered by the shape through
// Contact.Impact (ShapeContact). A slow touch where the ball's acceleration holds it on the shape settles it there instead: the rest of
// the step is flown with the shape as its support (Support). The main path is TryStep in FlightStepper.cs.
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Integration;
using MagnusBall.Integration.Kernels;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
        private readonly ContactShape[]? _shapes;
        // The shape the ball settled on earlier in this step (its index), or -1: the rest of the step is flown on it.
        private int _support = -1;

        // The earliest touch of a shape on the piece's Hermite (its time, the shape's index and normal there); false when none.
        private bool FindShapeContact(in HermiteSegment hermite, out double time, out int index, out Vector3d normal)
        {
            time = double.PositiveInfinity;
            index = -1;
            normal = Vector3d.Zero;
            ContactShape[] shapes = _shapes!;
            double h = hermite.Duration;
            if (!(h > 0))
            {
                return false;
            }

            Vector3d b0 = hermite.Start.Position, b3 = hermite.End.Position;
            Vector3d b1 = b0 + hermite.Start.Velocity * (h / 3), b2 = b3 - hermite.End.Velocity * (h / 3);
            var lo = new Vector3d(
                System.Math.Min(System.Math.Min(b0.X, b1.X), System.Math.Min(b2.X, b3.X)),
                System.Math.Min(System.Math.Min(b0.Y, b1.Y), System.Math.Min(b2.Y, b3.Y)),
                System.Math.Min(System.Math.Min(b0.Z, b1.Z), System.Math.Min(b2.Z, b3.Z)));
            var hi = new Vector3d(
                System.Math.Max(System.Math.Max(b0.X, b1.X), System.Math.Max(b2.X, b3.X)),
                System.Math.Max(System.Math.Max(b0.Y, b1.Y), System.Math.Max(b2.Y, b3.Y)),
                System.Math.Max(System.Math.Max(b0.Z, b1.Z), System.Math.Max(b2.Z, b3.Z)));
            double radius = Model.Ball.Radius;
            double best = double.PositiveInfinity;
            double tolerance = HermiteSegment.TimeTolerance / h;
            for (int i = 0; i < shapes.Length; i++)
            {
                if (i == _support || !ShapeSweep.MayTouch(shapes[i], lo, hi, radius))
                {
                    continue;
                }

                if (ShapeSweep.FirstContact(shapes[i], b0, b1, b2, b3, radius, tolerance, out double s, out Vector3d n) && s < best)
                {
                    best = s;
                    index = i;
                    normal = n;
                }
            }

            if (index < 0)
            {
                return false;
            }

            time = best >= 1 ? hermite.EndTime : hermite.StartTime + best * h;
            return true;
        }

        // The ball touches shape `index` at `contactTime` on the piece: the piece is cut there and the shape answers the ball
        // (Contact.Impact through ContactShape.Respond), or, a slow touch where its acceleration holds the ball on the shape, the ball
        // settles on it (its velocity into the shape removed) and the rest of the step is flown on it.
        private bool ShapeContact(in HermiteSegment hermite, double contactTime, int index, in Vector3d sweepNormal)
        {
            ContactShape shape = _shapes![index];
            FlightState touching = hermite.StateAt(contactTime);
            if (!touching.IsFinite || !hermite.TryUntil(contactTime, out HermiteSegment cut))
            {
                return false;
            }

            Vector3d normal = sweepNormal;
            double approach = -Vector3d.Dot(touching.Velocity, normal);
            double restSpeed = Contact?.RestNormalSpeed ?? GroundContact.DefaultRestNormalSpeed;
            // Held: the ball's whole acceleration there (gravity, drag, the Magnus force, the wind) presses it onto the shape.
            bool held = Vector3d.Dot(FlightKernel.DerivativeOf(Model, touching).Acceleration, normal) < 0;
            _now.Evaluations++;
            FlightState leaving;
            if (held && approach < restSpeed)
            {
                // Settles: the ball stays on the shape for the rest of the step (Support), with no event.
                leaving = new FlightState(touching.Position, touching.Velocity + normal * approach, touching.AngularVelocity, contactTime);
                _support = index;
            }
            else
            {
                ImpactOutcome outcome = shape.Respond(Model.Ball, touching.Position, touching.Velocity, touching.AngularVelocity, normal);
                if (!outcome.Velocity.IsFinite || !outcome.AngularVelocity.IsFinite)
                {
                    return false; // the impact law overflowed on an extreme impact
                }

                leaving = new FlightState(touching.Position, outcome.Velocity, outcome.AngularVelocity, contactTime);
                Write(new FlightEvent(shape.Id, touching, leaving, outcome.Regime, normal));
            }

            PushSegment(cut);
            _now.State = leaving;
            _now.Derivative = FlightKernel.DerivativeOf(Model, leaving);
            _now.Evaluations++;
            return true;
        }

        // A piece flown on the shape the ball settled on: where its end is inside the shape, the ball is put back on the
        // surface along the shape's normal and its velocity into it removed (one evaluation for the new derivative).
        private void Support(ref FlightState end, ref StateDerivative endDerivative)
        {
            ContactShape shape = _shapes![_support];
            double gap = shape.SignedDistance(end.Position, out Vector3d normal) - Model.Ball.Radius;
            if (!(gap < 0))
            {
                return; // off the shape (over an edge): it flies on
            }

            double into = Vector3d.Dot(end.Velocity, normal);
            Vector3d velocity = into < 0 ? end.Velocity - normal * into : end.Velocity;
            end = new FlightState(end.Position - normal * gap, velocity, end.AngularVelocity, end.Time);
            endDerivative = FlightKernel.DerivativeOf(Model, end);
            _now.Evaluations++;
        }
    }
}
