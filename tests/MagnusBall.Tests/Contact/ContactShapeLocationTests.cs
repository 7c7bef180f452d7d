using System;
using System.Collections.Generic;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>Where and when a contact is found (to 1e-12 s), on fixed and adaptive steps, and the sports' fixtures.</summary>
    public class ContactShapeLocationTests
    {
        private static readonly ContactProperties Steel = new ContactProperties(0.7, 0.3);

        [TestCase(1.0 / 30)]
        [TestCase(1.0 / 240)]
        [TestCase(0.5)]
        public void StraightPath_ContactTime_IsTheExactOne_To1e12Seconds(double step)
        {
            // No gravity, no air: the centre moves on a straight line, which the step's Hermite reproduces, so the touch time
            // is known in closed form. A capsule along z at x = 3, y = 0.02; the ball along x at 25 m/s.
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Vector3d.Zero);
            double r = 0.015, offset = 0.02, speed = 25;
            var post = new CapsuleShape(5, new Vector3d(3, offset, -1), new Vector3d(3, offset, 1), r, Steel);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { post });
            List<FlightEvent> events = ContactShapeTests.Fly(stepper, new FlightState(Vector3d.Zero, new Vector3d(speed, 0, 0), Vector3d.Zero), step, 1.0);
            FlightEvent hit = events.Find(e => e.Kind == FlightEventKinds.Contact);
            double reach = Ball.Tennis.Radius + r;
            double exact = (3 - Math.Sqrt(reach * reach - offset * offset)) / speed;
            Assert.That(hit.ShapeId, Is.EqualTo(5));
            Assert.That(hit.Time, Is.EqualTo(exact).Within(1e-12));
            Assert.That(hit.ContactNormal.Y, Is.LessThan(0), "the normal points from the post to the ball");
        }

        [Test]
        public void AdaptiveSteps_HitTheThinPost_Too()
        {
            FlightModel model = ContactShapeTests.Tennis();
            var post = new CylinderShape(2, new Vector3d(12, 0, -1), new Vector3d(12, 0, 3), 0.01, Steel);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { post });
            stepper.Reset(new FlightState(new Vector3d(0, 0.02, 1), new Vector3d(60, 0, 1), Vector3d.Zero));
            var method = new DormandPrince54();
            bool hit = false;
            for (int i = 0; i < 200 && !hit && stepper.State.Time < 1; i++)
            {
                Assert.That(stepper.TryStepAdaptive(method, 0.5), Is.Not.EqualTo(StepOutcome.Diverged));
                foreach (FlightEvent e in stepper.Events)
                {
                    hit |= e.Kind == FlightEventKinds.Contact && e.ShapeId == 2;
                }
            }

            Assert.That(hit, "an adaptive step of any length still finds the 2 cm post");
            Assert.That(stepper.State.Velocity.X, Is.LessThan(0), "and the ball comes back off it");
        }

        [Test]
        public void SportFixtures_AreWhereTheRulesPutThem()
        {
            ContactShape[] net = SportShapes.TennisNet(10, new Vector3d(11.885, 0, 0), Vector3d.UnitY, Vector3d.UnitZ);
            Assert.That(net.Length, Is.EqualTo(4 + 2 * SportShapes.TennisMeshPiecesPerHalf));
            int posts = net.Length - 2;
            double half = TennisCourt.DoublesWidthMetres / 2 + TennisCourt.PostsOutsideDoublesMetres;
            // The posts' centres 0.914 m outside the doubles sidelines (ITF rule 1): the post's surface one post radius away.
            Assert.That(net[posts].SignedDistance(new Vector3d(11.885, -half, 0.5), out _), Is.EqualTo(-SportShapes.TennisPostRadiusMetres).Within(1e-12));
            Assert.That(net[posts + 1].SignedDistance(new Vector3d(11.885, half, 0.5), out _), Is.EqualTo(-SportShapes.TennisPostRadiusMetres).Within(1e-12));
            // The cord's top at the centre is 0.914 m up, at the posts 1.07 m: the cord's axis is one cord radius below.
            double r = SportShapes.TennisCordRadiusMetres;
            Assert.That(net[0].SignedDistance(new Vector3d(11.885, 0, 0.914 - r), out _), Is.EqualTo(-r).Within(1e-12));
            Assert.That(net[0].SignedDistance(new Vector3d(11.885, -(TennisCourt.DoublesWidthMetres / 2 + TennisCourt.PostsOutsideDoublesMetres), 1.07 - r), out _),
                Is.EqualTo(-r).Within(1e-12));
            ContactShape[] goal = SportShapes.SoccerGoalFrame(20, Vector3d.Zero, Vector3d.UnitY, Vector3d.UnitZ);
            // 7.32 m between the posts' inner edges, 2.44 m to the bar's lower edge.
            Assert.That(goal[0].SignedDistance(new Vector3d(0, -3.66, 1), out _), Is.EqualTo(0).Within(1e-12));
            Assert.That(goal[1].SignedDistance(new Vector3d(0, 3.66, 1), out _), Is.EqualTo(0).Within(1e-12));
            Assert.That(goal[2].SignedDistance(new Vector3d(0, 0, 2.44), out _), Is.EqualTo(0).Within(1e-12));
            ContactShape[] hoop = SportShapes.BasketballHoop(30, Vector3d.Zero, Vector3d.UnitX, Vector3d.UnitZ);
            var rim = (TorusShape)hoop[0];
            Assert.That(rim.Centre.Z + rim.TubeRadiusM, Is.EqualTo(3.05).Within(1e-12), "the ring's upper edge 3.05 m up");
            Assert.That(rim.RingRadiusM - rim.TubeRadiusM, Is.EqualTo(0.225).Within(1e-12), "inside diameter 0.45 m");
            Assert.That(rim.Centre.X - rim.RingRadiusM + rim.TubeRadiusM, Is.EqualTo(0.15).Within(1e-12), "inside edge 0.15 m from the board");
            Assert.That(hoop[1].SignedDistance(new Vector3d(0.5, 0, 3.5), out Vector3d n), Is.EqualTo(0.5).Within(1e-12));
            Assert.That(n.X, Is.EqualTo(1).Within(1e-12));
            Assert.That(hoop[1].SignedDistance(new Vector3d(0, 0, 2.90 - 0.1), out _), Is.EqualTo(0.1).Within(1e-12), "lower edge 2.90 m up");
        }

        [Test]
        public void TennisNet_HasNoGap_UnderItsSaggingCord()
        {
            // A ball crossing the net line anywhere along it, at any height under the cord, touches the mesh or the cord: the
            // mesh pieces reach the cord's underside at their inner ends, so the gap under the cord is at most 2.6 cm, less than
            // a ball's 6.6 cm. Probed along the net (every 5 cm) and up to the cord: the nearest net shape is within a ball's
            // radius of the ball's centre on the net's plane.
            ContactShape[] net = SportShapes.TennisNet(10, new Vector3d(11.885, 0, 0), Vector3d.UnitY, Vector3d.UnitZ);
            double half = TennisCourt.DoublesWidthMetres / 2 + TennisCourt.PostsOutsideDoublesMetres;
            double radius = 0.033;
            int probes = 0;
            for (double y = -half + 0.05; y < half; y += 0.05)
            {
                double cordTop = 0.914 + (1.07 - 0.914) * Math.Abs(y) / half;
                for (double z = radius; z < cordTop; z += 0.01)
                {
                    double nearest = double.PositiveInfinity;
                    foreach (ContactShape shape in net)
                    {
                        nearest = Math.Min(nearest, shape.SignedDistance(new Vector3d(11.885, y, z), out _));
                    }

                    Assert.That(nearest, Is.LessThan(radius), $"a ball at y = {y:F2} m, z = {z:F2} m passes through the net");
                    probes++;
                }
            }

            Assert.That(probes, Is.GreaterThan(20_000));
        }

        [Test]
        public void BankShot_AtTheBackboard_NamesIt()
        {
            var model = new FlightModel(new Ball(0.62, 0.121, 2.0 / 3), Air.SeaLevel, Gravity.ZUp); // a size-7 basketball, drag-free
            ContactShape[] hoop = SportShapes.BasketballHoop(30, Vector3d.Zero, Vector3d.UnitX, Vector3d.UnitZ);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model), null, hoop);
            // From 4 m out, 2 m up, at the board just above the ring.
            List<FlightEvent> events = ContactShapeTests.Fly(stepper, new FlightState(new Vector3d(4, 0.3, 2), new Vector3d(-5.2, -0.35, 6.0), Vector3d.Zero), 1.0 / 120, 2);
            List<int> ids = events.FindAll(e => e.Kind == FlightEventKinds.Contact).ConvertAll(e => e.ShapeId);
            Assert.That(ids, Does.Contain(31), "the backboard");
            Assert.That(ids[0], Is.EqualTo(31));
        }
    }
}
