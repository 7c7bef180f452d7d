// FlightStepper, part: contact shapes (Contact/Shapes). A piece of flight or of a roll is searched for the first touch of each shape on
// its cubic Hermite (FindShapeContact, through Contact/Shapes/ShapeSweep.cs); a touch becomes a new piece of the step as a ground
// bounce does (HandleEvents in FlightStepper.Pieces.cs takes the earlier of the two), answered by the shape through Contact.Impact
// (ShapeContact). A slow touch where the ball's weight holds it on the shape settles it there: it rolls on the shape from then on
// (StartRollingOnShape, FlightStepper.Rolling.cs). The main path is TryStep in FlightStepper.cs.
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Integration;
using MagnusBall.Integration.Kernels;

namespace MagnusBall.Flight
{
    public sealed partial class FlightStepper
    {
        private readonly ContactShape[]? _shapes;

        // The earliest touch of a shape on the piece's Hermite (its time, the shape's index and normal there), less, for a rolling
        // ball, the shape it rolls on and a wall it rolls along; false when none.
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
            bool rolling = _now.Phase == FlightPhase.Rolling;
            double best = double.PositiveInfinity;
            double tolerance = HermiteSegment.TimeTolerance / h;
            for (int i = 0; i < shapes.Length; i++)
            {
                if ((rolling && (i == _now.RollShape || i == _now.RollWall)) || !ShapeSweep.MayTouch(shapes[i], lo, hi, radius))
                {
                    continue;
                }

                bool found = ShapeSweep.FirstContact(
                    shapes[i], b0, b1, b2, b3, radius, tolerance, ShapeSweep.MinApproachSpeed * h, out double s, out Vector3d n, out int visits);
                _now.SearchVisits += visits;
                if (found && s < best)
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
        // (Contact.Impact through ContactShape.Respond), or, a slow touch where the ball's weight and its whole acceleration hold it
        // on the shape, the ball settles on it and rolls on it from there. A stop kind naming Contact ends the flight at the touch.
        private bool ShapeContact(in HermiteSegment hermite, double contactTime, int index, in Vector3d normal, FlightEventKinds stopAt)
        {
            ContactShape shape = _shapes![index];
            if (!CutAt(hermite, contactTime, out FlightState touching, out HermiteSegment cut))
            {
                return false;
            }

            double approach = -Vector3d.Dot(touching.Velocity, normal);
            double restSpeed = Contact?.RestNormalSpeed ?? GroundContact.DefaultRestNormalSpeed;
            // A slow touch settles the ball where it is held there: gravity presses it onto the shape (a floor-like face, not a wall
            // or a ceiling), and so does its whole acceleration there (gravity, drag, the Magnus force, the wind; evaluated only then).
            if (approach < restSpeed && (stopAt & FlightEventKinds.Contact) == 0 && Vector3d.Dot(Model.Gravity, normal) < 0)
            {
                _now.Evaluations++;
                if (Vector3d.Dot(FlightKernel.DerivativeOf(Model, touching).Acceleration, normal) < 0)
                {
                    StartRollingOnShape(index, touching, normal);
                    Write(new FlightEvent(shape.Id, touching, _now.State, BounceRegime.None, normal, startsRolling: true));
                    return _now.State.IsFinite && _now.Derivative.IsFinite;
                }
            }

            if (!Answer(shape, touching, normal, cut, stopAt, out FlightState leaving))
            {
                return false;
            }

            if (_now.Phase != FlightPhase.Stopped)
            {
                FlyFrom(leaving);
            }

            return true;
        }

        // The shape answers the ball touching it along `normal` (Contact.Impact through ContactShape.Respond) and the Contact event is
        // written; a stop kind naming Contact ends the flight there (the ball arriving). False when the impact law overflowed on an
        // extreme impact (the caller refuses the step).
        private bool Answer(
            ContactShape shape, in FlightState touching, in Vector3d normal, in HermiteSegment cut, FlightEventKinds stopAt, out FlightState leaving)
        {
            ImpactOutcome outcome = shape.Respond(Model.Ball, touching.Position, touching.Velocity, touching.AngularVelocity, normal);
            leaving = new FlightState(touching.Position, outcome.Velocity, outcome.AngularVelocity, touching.Time);
            if (!outcome.Velocity.IsFinite || !outcome.AngularVelocity.IsFinite)
            {
                return false;
            }

            var contact = new FlightEvent(shape.Id, touching, leaving, outcome.Regime, normal, startsRolling: false);
            Write(contact);
            if ((stopAt & FlightEventKinds.Contact) != 0)
            {
                Stop(contact, cut.Duration > 0 ? cut.EndDerivative : _now.Derivative);
            }

            return true;
        }

        // The ball flies on from `state` (one evaluation for its derivative).
        private void FlyFrom(in FlightState state)
        {
            _now.Phase = FlightPhase.Flying;
            _now.State = state;
            _now.Derivative = FlightKernel.DerivativeOf(Model, state);
            _now.Evaluations++;
        }

        // The state where the piece touches at `time`, with the piece up to there stored; false when its dense output overflows
        // there (the caller refuses the step).
        private bool CutAt(in HermiteSegment segment, double time, out FlightState touching, out HermiteSegment cut)
        {
            touching = segment.StateAt(time);
            cut = default;
            if (!touching.IsFinite || !segment.TryUntil(time, out cut))
            {
                return false;
            }

            PushSegment(cut);
            return true;
        }

        // The step's pieces ran out (MaxPiecesPerStep) before its end: the ball is held where it is, with its velocity and spin,
        // until the end of the step, and goes on from there at the next one. Only a ball caught between surfaces (more contacts in
        // one step than the cap) gets here; it loses that part of a step of motion instead of passing through a surface.
        private void HoldUntil(double endTime)
        {
            FlightState s = _now.State;
            var still = new StateDerivative(Vector3d.Zero, Vector3d.Zero, Vector3d.Zero);
            PushSegment(new HermiteSegment(
                new FlightState(s.Position, Vector3d.Zero, s.AngularVelocity, s.Time), still,
                new FlightState(s.Position, Vector3d.Zero, s.AngularVelocity, endTime), still));
            _now.State = new FlightState(s.Position, s.Velocity, s.AngularVelocity, endTime);
        }
    }
}
