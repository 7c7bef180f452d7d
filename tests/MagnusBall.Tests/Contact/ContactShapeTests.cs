using System;
using System.Collections.Generic;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>Contact shapes in flight (issue 40): located on the dense output, never tunnelling, answered through Impact.</summary>
    public class ContactShapeTests
    {
        private static readonly ContactProperties Steel = new ContactProperties(0.7, 0.3);

        internal static FlightModel Tennis() => SportPresets.Tennis.CreateModel(Air.SeaLevel, Gravity.ZUp);

        // Flies until `seconds` with fixed steps, collecting every event.
        internal static List<FlightEvent> Fly(FlightStepper stepper, in FlightState start, double step, double seconds)
        {
            var events = new List<FlightEvent>();
            stepper.Reset(start);
            double end = start.Time + seconds;
            for (int i = 0; i < 100000; i++)
            {
                double h = FlightStepper.StepToward(stepper.State.Time, end, step, out bool last);
                Assert.That(stepper.TryStep(h), Is.Not.EqualTo(StepOutcome.Diverged));
                foreach (FlightEvent e in stepper.Events)
                {
                    events.Add(e);
                }

                if (last || stepper.IsStopped)
                {
                    break;
                }
            }

            return events;
        }

        private static FlightEvent FirstContact(List<FlightEvent> events) => events.Find(e => e.Kind == FlightEventKinds.Contact);

        [Test]
        public void FastBall_AtThinCylinder_WithLongSteps_HitsIt()
        {
            // 100 m/s at a 2 cm post with 1/30 s steps: a step carries the ball 3.3 m, the post is in the middle of one.
            FlightModel model = Tennis();
            var post = new CylinderShape(7, new Vector3d(1.7, 0, -1), new Vector3d(1.7, 0, 3), 0.01, Steel);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { post });
            var start = new FlightState(new Vector3d(0, 0.01, 1), new Vector3d(100, 0, 0), Vector3d.Zero);
            List<FlightEvent> events = Fly(stepper, start, 1.0 / 30, 0.1);
            FlightEvent hit = FirstContact(events);
            Assert.That(hit.Kind, Is.EqualTo(FlightEventKinds.Contact), "the post must be hit");
            Assert.That(hit.ShapeId, Is.EqualTo(7));
            // Located where the surfaces touch: centre distance to the axis = ball radius + post radius.
            double gap = post.SignedDistance(hit.Position, out Vector3d n) - model.Ball.Radius;
            Assert.That(Math.Abs(gap), Is.LessThan(1e-9), $"gap {gap}");
            Assert.That(Vector3d.Dot(n, hit.ContactNormal), Is.GreaterThan(1 - 1e-9));
            Assert.That(hit.After.Velocity.X, Is.LessThan(0), "it comes back off the post");
        }

        [TestCase(-1e-4, true)]
        [TestCase(-1e-6, true)]
        [TestCase(1e-6, false)]
        [TestCase(1e-4, false)]
        public void GrazingPass_IsClassifiedByWhetherTheSurfacesTouch(double clearance, bool hits)
        {
            // A vertical post: the ball's sideways offset from its axis stays exactly what it was launched with (gravity, drag
            // and the flight are in the x-z plane), so the pass clears the post by exactly `clearance`.
            FlightModel model = Tennis();
            double r = 0.01;
            var post = new CylinderShape(1, new Vector3d(5, 0, -2), new Vector3d(5, 0, 4), r, Steel);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { post });
            double offset = model.Ball.Radius + r + clearance;
            var start = new FlightState(new Vector3d(0, offset, 1), new Vector3d(40, 0, 2), Vector3d.Zero);
            List<FlightEvent> events = Fly(stepper, start, 1.0 / 60, 0.3);
            Assert.That(FirstContact(events).Kind == FlightEventKinds.Contact, Is.EqualTo(hits));
        }

        [Test]
        public void BallAtRest_OnTableTop_DoesNotFallThrough()
        {
            // Placed on the table at rest: it settles on the top (a Contact that starts rolling), comes to rest there (the flight
            // is over) and stays at the top's height to rounding.
            FlightModel model = Tennis();
            var table = new BoxShape(3, new Vector3d(0, 0, 0.74), new Vector3d(1.37, 0.76, 0.02), Vector3d.UnitX, Vector3d.UnitY, Steel);
            double top = 0.76 + model.Ball.Radius;
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { table });
            stepper.Reset(new FlightState(new Vector3d(0.2, 0.1, top), Vector3d.Zero, Vector3d.Zero));
            var events = new List<FlightEvent>();
            for (int i = 0; i < 600 && !stepper.IsStopped; i++)
            {
                Assert.That(stepper.TryStep(1.0 / 60), Is.Not.EqualTo(StepOutcome.Diverged));
                events.AddRange(stepper.Events.ToArray());
                Assert.That(stepper.State.Position.Z, Is.EqualTo(top).Within(1e-9), $"step {i}");
            }

            Assert.That(stepper.IsStopped, Is.True, "it comes to rest on the table");
            Assert.That(events.FindAll(e => e.Kind == FlightEventKinds.Contact && e.StartsRolling).Count, Is.EqualTo(1));
            Assert.That(stepper.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Rest));
            Assert.That(stepper.State.Velocity.Length, Is.LessThan(1e-9));
        }

        [Test]
        public void BallRollingAlongBoard_StaysOnIt_AndDropsOffItsEnd()
        {
            // Rolling (its spin matches its speed) at 3 m/s along a 2 m board: rolling resistance slows it (0.03 g), it stays on
            // the top to rounding, and past the board's end (x = 2 m) it flies off and falls.
            FlightModel model = Tennis();
            var board = new BoxShape(3, new Vector3d(1, 0, 0.5), new Vector3d(1, 0.3, 0.01), Vector3d.UnitX, Vector3d.UnitY, Steel);
            double top = 0.51 + model.Ball.Radius;
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { board });
            stepper.Reset(new FlightState(new Vector3d(0.1, 0, top), new Vector3d(3, 0, 0), new Vector3d(0, 3 / model.Ball.Radius, 0)));
            double lastX = 0.1;
            for (int i = 0; i < 60; i++)
            {
                stepper.TryStep(1.0 / 120);
                if (stepper.State.Position.X < 2)
                {
                    Assert.That(stepper.State.Position.Z, Is.EqualTo(top).Within(1e-9), $"step {i}");
                }

                Assert.That(stepper.State.Position.X, Is.GreaterThan(lastX));
                lastX = stepper.State.Position.X;
            }

            Assert.That(stepper.Phase, Is.EqualTo(FlightPhase.Rolling));
            // Past the end (x = 2 m) it falls.
            for (int i = 0; i < 120; i++)
            {
                stepper.TryStep(1.0 / 120);
            }

            Assert.That(stepper.State.Position.X, Is.GreaterThan(2));
            Assert.That(stepper.State.Position.Z, Is.LessThan(top - 0.05));
        }

        [Test]
        public void Contact_NeverCreatesEnergy_ImpulseAlongNormalWithinFrictionCone(
            [Values(0, 1, 2, 3, 4)] int shapeKind, [Values(-60.0, 0, 200.0)] double spin, [Values(5.0, 30.0)] double speed)
        {
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.ZUp); // a parabola: the shot arrives where aimed
            Ball ball = model.Ball;
            ContactShape shape = shapeKind switch
            {
                0 => new CapsuleShape(1, new Vector3d(3, -2, 1.2), new Vector3d(3, 2, 0.8), 0.02, Steel),
                1 => new TorusShape(1, new Vector3d(3, 0.27, 1), new Vector3d(0.2, 0, 1), 0.234, 0.009, Steel),
                2 => BoxShape.Rectangle(1, new Vector3d(3, 0, 1), new Vector3d(-1, 0.3, 0.2), Vector3d.UnitY, 2, 2, Steel),
                3 => new CapsuleShape(1, new Vector3d(3, -2, 1.05), new Vector3d(3, 2, 1.05), 0.02, Steel, effectiveMassKg: 0.3),
                _ => new SphereShape(1, new Vector3d(3.1, 0.12, 1.03), 0.1, Steel),
            };
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new[] { shape });
            // Launched to arrive near 1 m up at x = 3 m (about a vacuum arc).
            var start = new FlightState(new Vector3d(0, 0.05, 1), new Vector3d(speed, 0, 4.9 * 3 / speed), new Vector3d(0, spin, 30));
            FlightEvent hit = FirstContact(Fly(stepper, start, 1.0 / 120, 3.5 / speed));
            Assert.That(hit.Kind, Is.EqualTo(FlightEventKinds.Contact));
            double before = Energy(ball, hit.State), after = Energy(ball, hit.After);
            Assert.That(after, Is.LessThanOrEqualTo(before * (1 + 1e-12)), "no energy created");
            Vector3d impulse = (hit.After.Velocity - hit.State.Velocity) * ball.Mass;
            Vector3d n = hit.ContactNormal;
            double jn = Vector3d.Dot(impulse, n);
            double jt = (impulse - n * jn).Length;
            Assert.That(jn, Is.GreaterThan(0), "the impulse pushes the ball out");
            Assert.That(jt, Is.LessThanOrEqualTo(shape.Contact.Friction * jn * (1 + 1e-9) + 1e-15), "within the friction cone");
        }

        private static double Energy(Ball ball, in FlightState s) =>
            0.5 * ball.Mass * s.Velocity.LengthSquared + 0.5 * ball.InertiaFactor * ball.Mass * ball.Radius * ball.Radius * s.AngularVelocity.LengthSquared;

        [Test]
        public void MirrorShots_GiveMirrorResults()
        {
            // Mirror in y: positions and velocities (x, -y, z), angular velocity (a pseudovector) (-wx, wy, -wz).
            FlightModel model = Tennis();
            ContactShape[] Shapes(double sign) => new ContactShape[]
            {
                new CapsuleShape(1, new Vector3d(4, -1.5 * sign, 0.9), new Vector3d(4, 1.5 * sign, 1.1), 0.1, Steel),
                new TorusShape(2, new Vector3d(8, 0.2 * sign, 1), new Vector3d(0.1, 0.3 * sign, 1), 0.25, 0.01, Steel),
            };
            FlightState Launch(double sign) => new FlightState(new Vector3d(0, 0.1 * sign, 1), new Vector3d(20, 0.3 * sign, 1), new Vector3d(-10 * sign, 50, 20 * sign));
            List<FlightEvent> a = Fly(new FlightStepper(model, RungeKutta4.Instance, null, null, Shapes(1)), Launch(1), 1.0 / 120, 0.8);
            List<FlightEvent> b = Fly(new FlightStepper(model, RungeKutta4.Instance, null, null, Shapes(-1)), Launch(-1), 1.0 / 120, 0.8);
            Assert.That(a.Count, Is.GreaterThan(0));
            Assert.That(b.Count, Is.EqualTo(a.Count));
            for (int i = 0; i < a.Count; i++)
            {
                Assert.That(b[i].ShapeId, Is.EqualTo(a[i].ShapeId));
                Assert.That(b[i].Time, Is.EqualTo(a[i].Time).Within(1e-12));
                AssertMirror(a[i].After.Velocity, b[i].After.Velocity, 1);
                AssertMirror(a[i].After.AngularVelocity, b[i].After.AngularVelocity, -1);
            }
        }

        private static void AssertMirror(in Vector3d a, in Vector3d b, double parity)
        {
            double tol = 1e-9 * (1 + a.Length);
            Assert.That(b.X, Is.EqualTo(parity * a.X).Within(tol));
            Assert.That(b.Y, Is.EqualTo(-parity * a.Y).Within(tol));
            Assert.That(b.Z, Is.EqualTo(parity * a.Z).Within(tol));
        }

        [Test]
        public void FiniteMassShape_TakesSomeOfTheBounce()
        {
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.ZUp);
            FlightEvent Hit(double mass)
            {
                var bar = new CapsuleShape(1, new Vector3d(3, -2, 1), new Vector3d(3, 2, 1), 0.02, Steel, mass);
                return FirstContact(Fly(new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { bar }),
                    new FlightState(new Vector3d(0, 0, 1.25), new Vector3d(20, 0, -1), Vector3d.Zero), 1.0 / 120, 0.3));
            }

            FlightEvent fixedBar = Hit(double.PositiveInfinity), light = Hit(0.1);
            Assert.That(fixedBar.Kind, Is.EqualTo(FlightEventKinds.Contact));
            Assert.That(light.Kind, Is.EqualTo(FlightEventKinds.Contact));
            Assert.That(light.After.Velocity.Length, Is.LessThan(fixedBar.After.Velocity.Length));
        }

        [Test]
        public void NetMesh_CatchesTheBall_ItDrops()
        {
            FlightModel model = Tennis();
            var mesh = new NetMeshShape(9, new Vector3d(5, 0, 0.45), Vector3d.UnitX, Vector3d.UnitY, 12, 0.9);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model), null, new ContactShape[] { mesh });
            List<FlightEvent> events = Fly(stepper, new FlightState(new Vector3d(0, 0, 0.5), new Vector3d(30, 0, 1), new Vector3d(0, 200, 0)), 1.0 / 120, 3);
            FlightEvent hit = FirstContact(events);
            Assert.That(hit.ShapeId, Is.EqualTo(9));
            Assert.That(hit.After.Velocity.Length, Is.LessThan(0.15 * hit.State.Velocity.Length));
            FlightEvent landing = events.Find(e => e.Kind == FlightEventKinds.Landing);
            Assert.That(landing.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(landing.Position.X, Is.LessThan(5).And.GreaterThan(4), "drops in front of the net");
        }

        [TestCase(1.0 / 240)]
        [TestCase(1.0 / 30)]
        public void Sphere_IsHitWhereTheSurfacesTouch_AndAHeadOnHitComesStraightBack(double step)
        {
            // Straight at a 0.1 m sphere, in a vacuum with no gravity: the touch is at centre distance 0.1 + r, exactly where the
            // straight path puts it; the normal is along the path, so with no spin the ball comes straight back at e times its speed.
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Vector3d.Zero);
            double r = model.Ball.Radius;
            var sphere = new SphereShape(5, new Vector3d(4, 0, 1), 0.1, Steel);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { sphere });
            FlightEvent hit = FirstContact(Fly(stepper, new FlightState(new Vector3d(0, 0, 1), new Vector3d(40, 0, 0), Vector3d.Zero), step, 0.2));
            Assert.That(hit.ShapeId, Is.EqualTo(5));
            Assert.That(hit.Time, Is.EqualTo((4 - 0.1 - r) / 40).Within(1e-12));
            Assert.That(hit.ContactNormal.X, Is.EqualTo(-1).Within(1e-12));
            Assert.That(hit.After.Velocity.X, Is.EqualTo(-0.7 * 40).Within(1e-9));
        }

        [Test]
        public void NetMesh_OfFiniteMass_GivesWay()
        {
            // A fixed mesh sends the ball back at 0.1 of its normal speed. 1 kg of mesh moving with a 57 g ball sends it back
            // slower, at (m - e M)/(m + M) of it by the impact law. 0.2 kg is lighter than m/e: the impact law would leave the
            // ball still moving into the mesh, which stays where it is here, so the mesh gives way by taking that speed: the ball
            // leaves along it, and in flight it never passes the mesh.
            FlightModel model = Tennis();
            Ball ball = model.Ball;
            NetMeshShape Mesh(double mass) => new NetMeshShape(9, new Vector3d(5, 0, 0.45), Vector3d.UnitX, Vector3d.UnitY, 12, 0.9, effectiveMassKg: mass);
            var position = new Vector3d(5 - ball.Radius, 0, 0.45);
            var velocity = new Vector3d(30, 0, 0);
            double m = ball.Mass;
            Assert.That(Mesh(double.PositiveInfinity).Respond(ball, position, velocity, Vector3d.Zero, -Vector3d.UnitX).Velocity.X, Is.EqualTo(-0.1 * 30).Within(1e-9));
            Assert.That(Mesh(1).Respond(ball, position, velocity, Vector3d.Zero, -Vector3d.UnitX).Velocity.X, Is.EqualTo(30 * (m - 0.1 * 1) / (m + 1)).Within(1e-9));
            Assert.That(Mesh(0.2).Respond(ball, position, velocity, Vector3d.Zero, -Vector3d.UnitX).Velocity.X, Is.EqualTo(0));

            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, new GroundContact(CrossBounce.Hard, new Plane(Vector3d.Zero, Vector3d.UnitZ)),
                new ContactShape[] { Mesh(0.2) });
            stepper.Reset(new FlightState(new Vector3d(0, 0, 0.5), new Vector3d(30, 0, 0.5), Vector3d.Zero));
            for (int i = 0; i < 120 && !stepper.IsStopped; i++)
            {
                stepper.TryStep(1.0 / 60);
                Assert.That(stepper.State.Position.X, Is.LessThanOrEqualTo(5 - ball.Radius + 1e-9), $"step {i}");
            }
        }

        [Test]
        public void Driver_TakesShapes_AndReportsTheContact()
        {
            FlightModel model = Tennis();
            var wall = BoxShape.Rectangle(4, new Vector3d(6, 0, 1), -Vector3d.UnitX, Vector3d.UnitY, 4, 2, Steel);
            var driver = new FixedStepDriver(model, RungeKutta4.Instance, 1.0 / 60, new FlightState(new Vector3d(0, 0, 1), new Vector3d(25, 0, 3), Vector3d.Zero),
                shapes: new ContactShape[] { wall });
            var buffer = new FlightEvent[64];
            bool hit = false;
            for (int frame = 0; frame < 60 && !hit; frame++)
            {
                AdvanceResult r = driver.Advance(1.0 / 60, buffer);
                for (int i = 0; i < r.EventCount; i++)
                {
                    hit |= buffer[i].Kind == FlightEventKinds.Contact && buffer[i].ShapeId == 4;
                }
            }

            Assert.That(hit);
        }

        [Test]
        public void ContactFlight_AllocatesNothingPerStep()
        {
            FlightModel model = Tennis();
            ContactShape[] shapes = MagnusBall.Shots.SportShapes.TennisNet(0, new Vector3d(11.885, 0, 0), Vector3d.UnitY, Vector3d.UnitZ);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model), null, shapes);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 0, 2), new Vector3d(0, 100, 0));
            Action run = () =>
            {
                stepper.Reset(start);
                for (int i = 0; i < 240 && !stepper.IsStopped; i++)
                {
                    stepper.TryStep(1.0 / 240, FlightEventKinds.Landing);
                }
            };
            Assert.That(Allocation.SteadyStateBytes(run), Is.EqualTo(0));
        }
    }
}
