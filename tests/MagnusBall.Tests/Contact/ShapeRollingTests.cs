using System;
using System.Collections.Generic;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// A rolling or settled ball and the shapes (issue 40): a ball rolling on the ground meets the shapes on it, a ball settled on a
    /// shape rolls on it and stays on it for any step, a slow touch is an event, stop kinds name contacts, and a ball caught between
    /// surfaces never passes through one.
    /// </summary>
    public class ShapeRollingTests
    {
        private static readonly ContactProperties Wood = new ContactProperties(0.7, 0.3);

        private static GroundContact Ground() => new GroundContact(CrossBounce.Hard, new Plane(Vector3d.Zero, Vector3d.UnitZ));

        // A 10 cm thick wall across x = 3 m (its face toward the ball at x = 2.95 m), standing on the ground.
        private static BoxShape Wall() =>
            new BoxShape(4, new Vector3d(3, 0, 0.5), new Vector3d(0.05, 2, 0.5), Vector3d.UnitX, Vector3d.UnitY, Wood);

        // Flies with fixed steps, checking after every step that the ball is not inside any shape, and collects the events.
        private static List<FlightEvent> FlyOutside(FlightStepper stepper, ContactShape[] shapes, double radius, double step, double seconds)
        {
            var events = new List<FlightEvent>();
            double end = stepper.State.Time + seconds;
            for (int i = 0; i < 100000 && !stepper.IsStopped; i++)
            {
                double h = FlightStepper.StepToward(stepper.State.Time, end, step, out bool last);
                Assert.That(stepper.TryStep(h), Is.Not.EqualTo(StepOutcome.Diverged));
                events.AddRange(stepper.Events.ToArray());
                foreach (ContactShape shape in shapes)
                {
                    double gap = shape.SignedDistance(stepper.State.Position, out _) - radius;
                    Assert.That(gap, Is.GreaterThan(-1e-9), $"inside shape {shape.Id} after step {i} (t = {stepper.State.Time})");
                }

                if (last)
                {
                    break;
                }
            }

            return events;
        }

        [TestCase(1.0 / 60)]
        [TestCase(0.25)]
        [TestCase(2.0)]
        public void BallRollingOnTheGround_MeetsAWall_ForAnyStep(double step)
        {
            // Rolling at 4 m/s toward the wall 2.9 m away: with steps up to 2 s (8 m of roll in one step) it hits the wall, where
            // the surfaces touch, and comes back.
            FlightModel model = ContactShapeTests.Tennis();
            double r = model.Ball.Radius;
            BoxShape wall = Wall();
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { wall });
            stepper.Reset(new FlightState(new Vector3d(0, 0, r), new Vector3d(4, 0, 0), new Vector3d(0, 4 / r, 0)));
            Assert.That(stepper.Phase, Is.EqualTo(FlightPhase.Rolling));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { wall }, r, step, 8);
            FlightEvent hit = events.Find(e => e.Kind == FlightEventKinds.Contact);
            Assert.That(hit.ShapeId, Is.EqualTo(4), "the wall is hit");
            Assert.That(hit.Position.X, Is.EqualTo(2.95 - r).Within(1e-9), "where the surfaces touch");
            Assert.That(hit.After.Velocity.X, Is.LessThan(0), "it comes back off the wall");
            Assert.That(stepper.State.Position.X, Is.LessThan(2.95 - r + 1e-9));
        }

        [TestCase(0.1)]
        [TestCase(1.0)]
        public void BallSettledOnATable_WithLongSteps_NeverReachesTheGround(double step)
        {
            // Dropped on a 2.5 cm table top 0.75 m above the ground: it bounces, settles and rolls on the top; steps of 0.1 s and
            // 1 s (a free fall of 5 cm and 4.9 m) must not carry it through the top to the ground.
            FlightModel model = ContactShapeTests.Tennis();
            double r = model.Ball.Radius;
            var table = new BoxShape(3, new Vector3d(0, 0, 0.75), new Vector3d(1, 1, 0.0125), Vector3d.UnitX, Vector3d.UnitY, Wood);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { table });
            stepper.Reset(new FlightState(new Vector3d(0.2, 0, 1.2), new Vector3d(0.3, 0, 0), Vector3d.Zero));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { table }, r, step, 10);
            Assert.That(events.Exists(e => e.Kind == FlightEventKinds.Bounce), Is.False, "it never reaches the ground");
            Assert.That(events.FindAll(e => e.Kind == FlightEventKinds.Contact && e.StartsRolling).Count, Is.EqualTo(1), "it settles once");
            Assert.That(stepper.IsStopped, Is.True);
            Assert.That(stepper.State.Position.Z, Is.EqualTo(0.7625 + r).Within(1e-9), "at rest on the top");
        }

        [Test]
        public void BallSettledOnATable_Adaptive_NeverReachesTheGround()
        {
            // The adaptive method grows its steps without bound on a parabola (its error estimate is zero there): the settled ball
            // must stay on the table however long they get.
            FlightModel model = ContactShapeTests.Tennis();
            double r = model.Ball.Radius;
            var table = new BoxShape(3, new Vector3d(0, 0, 0.75), new Vector3d(1, 1, 0.0125), Vector3d.UnitX, Vector3d.UnitY, Wood);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { table });
            stepper.Reset(new FlightState(new Vector3d(0.2, 0, 1.2), new Vector3d(0.3, 0, 0), Vector3d.Zero));
            var method = new DormandPrince54(1e-6, 1e-6);
            for (int i = 0; i < 2000 && !stepper.IsStopped && stepper.State.Time < 30; i++)
            {
                Assert.That(stepper.TryStepAdaptive(method, 10), Is.Not.EqualTo(StepOutcome.Diverged));
                foreach (FlightEvent e in stepper.Events)
                {
                    Assert.That(e.Kind, Is.Not.EqualTo(FlightEventKinds.Bounce), $"reached the ground at t = {e.Time}");
                }
            }

            Assert.That(stepper.IsStopped, Is.True);
            Assert.That(stepper.State.Position.Z, Is.EqualTo(0.7625 + r).Within(1e-9));
        }

        [Test]
        public void SlowTouch_IsOneEvent_ThatSaysTheBallSettled()
        {
            // Lowered onto the table at 5 cm/s (below the rest speed, 0.1 m/s): one Contact event, StartsRolling, its After on the
            // top with no velocity into it; later steps write no more.
            FlightModel model = ContactShapeTests.Tennis();
            double r = model.Ball.Radius;
            var table = new BoxShape(3, new Vector3d(0, 0, 0.75), new Vector3d(1, 1, 0.0125), Vector3d.UnitX, Vector3d.UnitY, Wood);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { table });
            stepper.Reset(new FlightState(new Vector3d(0, 0, 0.7625 + r + 1e-4), new Vector3d(0.2, 0, -0.05), new Vector3d(0, 0.2 / r, 0)));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { table }, r, 1.0 / 60, 5);
            List<FlightEvent> contacts = events.FindAll(e => e.Kind == FlightEventKinds.Contact);
            Assert.That(contacts.Count, Is.EqualTo(1));
            Assert.That(contacts[0].StartsRolling, Is.True);
            Assert.That(contacts[0].ShapeId, Is.EqualTo(3));
            Assert.That(contacts[0].After.Velocity.Z, Is.EqualTo(0).Within(1e-12));
            Assert.That(contacts[0].ContactNormal.Z, Is.EqualTo(1).Within(1e-12));
        }

        [Test]
        public void StopAtContact_EndsTheFlightAtTheTouch()
        {
            // A stop kind that names Contact ends the flight where the ball touches the post, the ball arriving.
            FlightModel model = ContactShapeTests.Tennis();
            var post = new CylinderShape(7, new Vector3d(1.7, 0, -1), new Vector3d(1.7, 0, 3), 0.01, Wood);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { post });
            stepper.Reset(new FlightState(new Vector3d(0, 0.01, 1), new Vector3d(30, 0, 0), Vector3d.Zero));
            StepOutcome outcome = StepOutcome.Taken;
            for (int i = 0; i < 60 && outcome == StepOutcome.Taken; i++)
            {
                outcome = stepper.TryStep(1.0 / 30, FlightEventKinds.Contact);
            }

            Assert.That(outcome, Is.EqualTo(StepOutcome.Stopped));
            Assert.That(stepper.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Contact));
            Assert.That(stepper.StopEvent.ShapeId, Is.EqualTo(7));
            Assert.That(stepper.State.Velocity.X, Is.GreaterThan(0), "the state is the ball arriving");
            Assert.That(post.SignedDistance(stepper.State.Position, out _) - model.Ball.Radius, Is.EqualTo(0).Within(1e-9));
        }

        [Test]
        public void StopAtBounce_EndsTheFlightAtTheFirstBounce()
        {
            FlightModel model = ContactShapeTests.Tennis();
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground());
            stepper.Reset(new FlightState(new Vector3d(0, 0, 1), new Vector3d(10, 0, 2), Vector3d.Zero));
            StepOutcome outcome = StepOutcome.Taken;
            for (int i = 0; i < 600 && outcome == StepOutcome.Taken; i++)
            {
                outcome = stepper.TryStep(1.0 / 60, FlightEventKinds.Bounce);
            }

            Assert.That(outcome, Is.EqualTo(StepOutcome.Stopped));
            Assert.That(stepper.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Bounce));
            Assert.That(stepper.State.Position.Z, Is.EqualTo(model.Ball.Radius).Within(1e-9));
            Assert.That(stepper.State.Velocity.Z, Is.LessThan(0), "the state is the ball arriving");
        }

        [Test]
        public void BallRollingDownASlope_IntoAWall_ComesToRestAgainstIt()
        {
            // The ground tilted 20 degrees toward the wall: the slope alone would keep the ball rolling (tan 20 deg against a
            // rolling resistance of 0.03), so only the wall can stop it. It bounces off the wall until it arrives slower than the
            // rest speed, then rests against it; it never passes into it.
            double tilt = 20 * Math.PI / 180;
            var gravity = new Vector3d(9.81 * Math.Sin(tilt), 0, -9.81 * Math.Cos(tilt)); // downhill is +x in the ground's frame
            var model = new FlightModel(Ball.Tennis, Air.SeaLevel, gravity);
            double r = model.Ball.Radius;
            BoxShape wall = Wall();
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { wall });
            stepper.Reset(new FlightState(new Vector3d(0, 0, r), new Vector3d(1, 0, 0), new Vector3d(0, 1 / r, 0)));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { wall }, r, 1.0 / 60, 30);
            Assert.That(stepper.IsStopped, Is.True, "it rests against the wall");
            Assert.That(stepper.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Rest));
            Assert.That(stepper.State.Position.X, Is.EqualTo(2.95 - r).Within(1e-6));
            Assert.That(events.FindAll(e => e.Kind == FlightEventKinds.Contact).Count, Is.GreaterThan(1));
        }

        [Test]
        public void BallCaughtBetweenTwoWalls_NeverPassesThrough()
        {
            // Two walls 7 cm apart (a tennis ball is 6.6 cm across) and a ball shot between them at 60 m/s across the gap, in a
            // vacuum with no gravity: hundreds of contacts a step, far more than a step's pieces. The ball is held at its last
            // contact for the rest of such a step instead of flying on through a wall.
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Vector3d.Zero);
            double r = model.Ball.Radius;
            var hard = new ContactProperties(1.0, 0);
            var left = new BoxShape(1, new Vector3d(0, -0.035 - 0.05, 0), new Vector3d(1, 0.05, 1), Vector3d.UnitX, Vector3d.UnitY, hard);
            var right = new BoxShape(2, new Vector3d(0, 0.035 + 0.05, 0), new Vector3d(1, 0.05, 1), Vector3d.UnitX, Vector3d.UnitY, hard);
            var shapes = new ContactShape[] { left, right };
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, shapes);
            stepper.Reset(new FlightState(Vector3d.Zero, new Vector3d(0.1, 60, 0), Vector3d.Zero));
            List<FlightEvent> events = FlyOutside(stepper, shapes, r, 1.0 / 30, 1);
            Assert.That(events.Count, Is.GreaterThan(FlightStepper.MaxPiecesPerStep));
            Assert.That(Math.Abs(stepper.State.Position.Y), Is.LessThan(0.035 - r + 1e-9));
        }

        [Test]
        public void GroundBounce_CarriesTheGroundsNormal_AsAContactCarriesTheShapes()
        {
            // The ground is one case of a contact: its bounce event says the normal it was answered along, as a shape's does.
            FlightModel model = ContactShapeTests.Tennis();
            Vector3d normal = new Vector3d(0.1, 0, 1).NormalizedOrZero();
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, new GroundContact(CrossBounce.Hard, new Plane(Vector3d.Zero, normal)));
            stepper.Reset(new FlightState(new Vector3d(0, 0, 1), new Vector3d(10, 0, 2), Vector3d.Zero));
            var events = new List<FlightEvent>();
            for (int i = 0; i < 240 && !events.Exists(e => e.Kind == FlightEventKinds.Bounce); i++)
            {
                stepper.TryStep(1.0 / 240);
                events.AddRange(stepper.Events.ToArray());
            }

            FlightEvent bounce = events.Find(e => e.Kind == FlightEventKinds.Bounce);
            Assert.That(bounce.Kind, Is.EqualTo(FlightEventKinds.Bounce));
            Assert.That(bounce.ShapeId, Is.EqualTo(-1));
            Assert.That((bounce.ContactNormal - normal).Length, Is.LessThan(1e-15));
        }

        [Test]
        public void BallRollingDownARamp_ReachesTheGround_AndNeverGoesBelowIt()
        {
            // A 15 degree ramp whose top face runs into the ground: the ball settles near its top, rolls down, and meets the ground
            // where the ramp does (a Bounce), never passing below the ground's plane of centres.
            FlightModel model = ContactShapeTests.Tennis();
            double r = model.Ball.Radius;
            double th = 15 * Math.PI / 180;
            var x = new Vector3d(Math.Cos(th), 0, -Math.Sin(th));
            var ramp = new BoxShape(5, Vector3d.Zero, new Vector3d(2, 1, 0.5), x, Vector3d.UnitY, Wood);
            Vector3d n = ramp.ZAxis;
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { ramp });
            stepper.Reset(new FlightState(n * (0.5 + r + 1e-4) - x * 1.0, Vector3d.Zero, Vector3d.Zero));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { ramp }, r, 1.0 / 60, 10);
            Assert.That(events.Exists(e => e.Kind == FlightEventKinds.Contact && e.StartsRolling), Is.True, "it settles on the ramp");
            Assert.That(events.Exists(e => e.Kind == FlightEventKinds.Bounce), Is.True, "it meets the ground");
            Assert.That(stepper.State.Position.Z, Is.GreaterThan(r - 1e-9));
        }

        [Test]
        public void BallRollingAlongAWall_ItIsPressedAgainst_RollsOnAlongIt()
        {
            // The ground tilted 20 degrees toward a long wall and a ball rolling at 3 m/s along it, 1 mm off: it touches the wall
            // and rolls on along it (pressed against it by the slope), never into it, instead of being stopped there.
            double tilt = 20 * Math.PI / 180;
            var model = new FlightModel(Ball.Tennis, Air.SeaLevel, new Vector3d(9.81 * Math.Sin(tilt), 0, -9.81 * Math.Cos(tilt)));
            double r = model.Ball.Radius;
            var wall = new BoxShape(4, new Vector3d(3, 0, 0.5), new Vector3d(0.05, 50, 0.5), Vector3d.UnitX, Vector3d.UnitY, Wood);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { wall });
            stepper.Reset(new FlightState(new Vector3d(2.95 - r - 0.001, 0, r), new Vector3d(0, 3, 0), new Vector3d(-3 / r, 0, 0)));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { wall }, r, 1.0 / 60, 1);
            Assert.That(events.FindAll(e => e.Kind == FlightEventKinds.Contact).Count, Is.EqualTo(1), "one touch, then along the wall");
            Assert.That(stepper.Phase, Is.EqualTo(FlightPhase.Rolling));
            Assert.That(stepper.State.Position.Y, Is.GreaterThan(2.5), "it rolled on along the wall (3 m/s less rolling resistance)");
            Assert.That(stepper.State.Position.X, Is.EqualTo(2.95 - r).Within(1e-6), "against the wall");
        }

        [TestCase(10.0)]
        [TestCase(-10.0)]
        public void BallRollingAlongALeaningWall_StaysAgainstIt_NotInIt(double leanDegrees)
        {
            // As above, with the wall leaning over the ball (or away from it) by 10 degrees: the wall takes away the ball's motion toward
            // it within the ground's plane. Taking away the motion along the wall's own normal left the ball a part of it into the wall
            // (shape fuzz: a golf ball rolling along a leaning box sank 2.4 cm into it in 1.6 s, the same at 1/60 s and in one step).
            double tilt = 20 * Math.PI / 180, lean = leanDegrees * Math.PI / 180;
            var model = new FlightModel(Ball.Tennis, Air.SeaLevel, new Vector3d(9.81 * Math.Sin(tilt), 0, -9.81 * Math.Cos(tilt)));
            double r = model.Ball.Radius;
            var xAxis = new Vector3d(Math.Cos(lean), 0, Math.Sin(lean));
            var wall = new BoxShape(4, new Vector3d(3, 0, 0.5), new Vector3d(0.05, 50, 0.5), xAxis, Vector3d.UnitY, Wood);
            // The ball on the ground 1 mm from the wall's face (x' . (p - c) = -0.05 - r - 0.001).
            double x = 3 + (-0.05 - r - 0.001 - Math.Sin(lean) * (r - 0.5)) / Math.Cos(lean);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { wall });
            stepper.Reset(new FlightState(new Vector3d(x, 0, r), new Vector3d(0, 3, 0), new Vector3d(-3 / r, 0, 0)));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { wall }, r, 1.0 / 60, 1);
            Assert.That(events.FindAll(e => e.Kind == FlightEventKinds.Contact).Count, Is.EqualTo(1), "one touch, then along the wall");
            Assert.That(stepper.Phase, Is.EqualTo(FlightPhase.Rolling));
            Assert.That(stepper.State.Position.Y, Is.GreaterThan(2.5), "it rolled on along the wall");
            Assert.That(wall.SignedDistance(stepper.State.Position, out _) - r, Is.EqualTo(0).Within(1e-6), "against the wall");
        }

        [Test]
        public void BallOnTheInsideOfARim_StaysOutOfTheTube()
        {
            // Settled on the inner side of a basketball rim (where the tangent plane cuts into the tube) and moving 1 m/s round the
            // ring: after every step it is on or outside the tube's surface, never in it, until it falls off.
            FlightModel model = ContactShapeTests.Tennis();
            double r = model.Ball.Radius;
            double ring = 0.2286, tube = 0.008, beta = 60 * Math.PI / 180;
            var rim = new TorusShape(9, new Vector3d(0, 0, 3), Vector3d.UnitZ, ring, tube, Wood);
            var n = new Vector3d(-Math.Cos(beta), 0, Math.Sin(beta));
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { rim });
            stepper.Reset(new FlightState(new Vector3d(ring, 0, 3) + n * (r + tube + 1e-5), new Vector3d(0, 1.0, 0) - n * 0.02, Vector3d.Zero));
            List<FlightEvent> events = FlyOutside(stepper, new ContactShape[] { rim }, r, 1.0 / 60, 0.5);
            Assert.That(events.Exists(e => e.Kind == FlightEventKinds.Contact && e.StartsRolling), Is.True, "it settles on the rim");
        }

        [Test]
        public void BallRollingOffABar_LeavesItAsWithShortSteps()
        {
            // On top of a horizontal 5 cm bar at 0.3 m/s: it rolls over and falls off. The time it takes to fall below the bar's axis
            // at 1/60 s steps is within 10 % of the time at 1/6000 s (the tangent plane is re-anchored on the bar at each step's end,
            // so it does not hop along it).
            double BelowTheAxis(double step)
            {
                FlightModel model = ContactShapeTests.Tennis();
                double r = model.Ball.Radius;
                var bar = new CapsuleShape(6, new Vector3d(0, -2, 1), new Vector3d(0, 2, 1), 0.05, Wood);
                var stepper = new FlightStepper(model, RungeKutta4.Instance, null, Ground(), new ContactShape[] { bar });
                stepper.Reset(new FlightState(new Vector3d(0, 0, 1 + 0.05 + r + 1e-5), new Vector3d(0.3, 0, 0), new Vector3d(0, 0.3 / r, 0)));
                for (int i = 0; i < (int)(3 / step) && !stepper.IsStopped; i++)
                {
                    stepper.TryStep(step);
                    Assert.That(stepper.Events.Length, Is.LessThanOrEqualTo(2), "no flood of events");
                    if (stepper.State.Position.Z < 1)
                    {
                        return stepper.State.Time;
                    }
                }

                return double.NaN;
            }

            double fine = BelowTheAxis(1.0 / 6000), frame = BelowTheAxis(1.0 / 60);
            Assert.That(frame, Is.EqualTo(fine).Within(0.1 * fine));
        }

        // A 20 m table whose top face is z = 0.
        private static BoxShape BigTable() =>
            new BoxShape(0, new Vector3d(0, 0, -10), new Vector3d(10, 10, 10), Vector3d.UnitX, Vector3d.UnitY, new ContactProperties(0.2, 0.4));

        [TestCase(2.0, 1.0 / 60)]
        [TestCase(6.0, 1.0 / 60)]
        [TestCase(12.0, 1.0 / 60)]
        [TestCase(6.0, 0.5)]
        public void BallLeavingATableTopSlowly_ComesBackToIt_NotIntoIt(double speed, double step)
        {
            // On the top at `speed` along it, leaving it at 2 cm/s: it is back on the top after 4 ms. The search for that touch must not
            // be used up by the path's run along the top (shape fuzz, finding F1: from 4 m/s at 1/60 s the ball sank into the table,
            // about 0.9 mm a frame).
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.ZUp);
            double r = model.Ball.Radius;
            var shapes = new ContactShape[] { BigTable() };
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, shapes);
            stepper.Reset(new FlightState(new Vector3d(0, 0, r), new Vector3d(speed, 0, 0.02), Vector3d.Zero));
            List<FlightEvent> events = FlyOutside(stepper, shapes, r, step, 1);
            Assert.That(events.Count, Is.GreaterThan(0), "it touched the top again");
        }

        [Test]
        public void BallDroppedOntoATableTop_KeepsBouncingOnIt_InOneLongStep()
        {
            // From 1 cm above the top at 6 m/s along it, in one 0.5 s step: its bounces get lower and closer together, and each is
            // found (finding F1: the third was missed and the ball ended 1 m inside the table).
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.ZUp);
            double r = model.Ball.Radius;
            var shapes = new ContactShape[] { BigTable() };
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, shapes);
            stepper.Reset(new FlightState(new Vector3d(0, 0, r + 0.01), new Vector3d(6, 0, -0.5), Vector3d.Zero));
            FlyOutside(stepper, shapes, r, 0.5, 0.5);
        }
    }
}
