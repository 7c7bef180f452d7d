using System;
using System.Collections.Generic;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>
    /// Issue 40, item 5: aiming with the world. The aim solvers treat their shapes as obstacles (an answer that touches one
    /// before it reaches the target is not a solution) and aim a bank shot off a named shape.
    /// </summary>
    [TestFixture]
    public class AimShapesTests
    {
        private static readonly FlightModel Tennis = SportPresets.Tennis.CreateModel(Air.SeaLevel, Gravity.ZUp);
        private static readonly FlightModel Basketball = SportPresets.Basketball.CreateModel(Air.SeaLevel, Gravity.ZUp);
        private static readonly Plane Ground = new Plane(default, Vector3d.UnitZ);
        private static readonly LaunchSpin Topspin = new LaunchSpin(20 * 2 * Math.PI);

        // The tennis net across the court at x = 11.885 (ids 0-4: cord halves, mesh, posts).
        private static ContactShape[] Net() => SportShapes.TennisNet(0, new Vector3d(11.885, 0, 0), Vector3d.UnitY, Vector3d.UnitZ);

        // The hoop at x = 5 facing back toward the shooter at the origin (ids 10: ring, 11: board).
        private static ContactShape[] Hoop() => SportShapes.BasketballHoop(10, new Vector3d(5, 0, 0), -Vector3d.UnitX, Vector3d.UnitZ);

        private static AimSolver Solver(FlightModel model, ContactShape[]? shapes, bool adaptive, double maximumElevation = 80) =>
            adaptive
                ? new AimSolver(model, Ground, maximumFlightTime: 5, maximumElevationDegrees: maximumElevation, shapes: shapes)
                : new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, Ground, maximumFlightTime: 5, maximumElevationDegrees: maximumElevation, shapes: shapes);

        // The solution flown again among the shapes, to its landing: every contact event, in order.
        private static List<FlightEvent> Contacts(FlightModel model, ContactShape[] shapes, Vector3d position, in AimSolution s)
        {
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model), null, shapes);
            stepper.Reset(new FlightState(position, s.Velocity, s.AngularVelocity));
            var contacts = new List<FlightEvent>();
            for (int i = 0; i < 240 * 5 && !stepper.IsStopped; i++)
            {
                stepper.TryStep(1.0 / 240, FlightEventKinds.Landing);
                foreach (FlightEvent e in stepper.Events.ToArray())
                {
                    if (e.Kind == FlightEventKinds.Contact)
                    {
                        contacts.Add(e);
                    }
                }
            }

            return contacts;
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ATennisDrive_AimedWithTheNet_ClearsTheCord_FlownAgain(bool adaptive)
        {
            var from = new Vector3d(0, 0, 1);
            var target = new Vector3d(21, 0, 0);
            AimSolution s = Solver(Tennis, Net(), adaptive).ElevationToReach(from, 30, Topspin, target);
            Assert.That(s.Status, Is.EqualTo(AimStatus.Solved));
            Assert.That(s.Miss, Is.LessThan(1e-6));
            Assert.That(Contacts(Tennis, Net(), from, s), Is.Empty, "flown again among the net's shapes, it touches none");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ADriveTheNetStops_IsAnsweredByTheLobOverIt(bool adaptive)
        {
            // Hit low and hard at a target just over the net: the flat solution goes into the mesh.
            var from = new Vector3d(6, 0, 0.4);
            var target = new Vector3d(14, 0, 0);
            AimSolution free = Solver(Tennis, null, adaptive).ElevationToReach(from, 25, LaunchSpin.None, target);
            Assert.That(free.Status, Is.EqualTo(AimStatus.Solved));
            Assert.That(Contacts(Tennis, Net(), from, free), Is.Not.Empty, "without the shapes the solver answers a drive into the net");

            AimSolution s = Solver(Tennis, Net(), adaptive).ElevationToReach(from, 25, LaunchSpin.None, target);
            Assert.That(s.Status, Is.EqualTo(AimStatus.Solved));
            Assert.That(s.ElevationRadians, Is.GreaterThan(free.ElevationRadians + 0.5), "the lob");
            Assert.That(Contacts(Tennis, Net(), from, s), Is.Empty);
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ATargetOnlyReachableThroughTheNet_IsBlocked(bool adaptive)
        {
            // Low, just beyond the net, with elevations capped at 5 degrees: every launch that reaches it meets the net (even the
            // 5 degree limit, the high arc's answer, passes the net below the cord).
            var from = new Vector3d(9, 0, 0.5);
            var target = new Vector3d(13, 0, 0.3);
            AimSolver solver = Solver(Tennis, Net(), adaptive, maximumElevation: 5);
            Assert.That(solver.ElevationToReach(from, 20, LaunchSpin.None, target).Status, Is.EqualTo(AimStatus.Blocked));
            Assert.That(solver.SpeedToReach(from, 0.05, 0, LaunchSpin.None, target).Status, Is.EqualTo(AimStatus.Blocked));
            Assert.That(Solver(Tennis, null, adaptive, maximumElevation: 5).ElevationToReach(from, 20, LaunchSpin.None, target).Status,
                Is.EqualTo(AimStatus.Solved), "without the net it is reached");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ABankShot_OffTheBackboard_ReachesTheRimsCentrePlane(bool adaptive)
        {
            ContactShape[] hoop = Hoop();
            var rimCentre = ((TorusShape)hoop[0]).Centre;
            var from = new Vector3d(0, 0, 2.2);
            AimSolution s = Solver(Basketball, hoop, adaptive).ElevationToReach(from, 9, LaunchSpin.None, rimCentre, viaShapeId: 11);
            Assert.That(s.Status, Is.EqualTo(AimStatus.Solved), s.ToString());
            Assert.That(s.Miss, Is.LessThan(1e-6), "the crossing of the rim's centre plane, at the rim's centre");
            Assert.That(s.Arrival.Velocity.X, Is.LessThan(0), "coming back off the board");
            Assert.That(s.Arrival.Velocity.Z, Is.LessThan(0), "coming down into the ring");
            TestContext.Out.WriteLine(s.ToString());

            List<FlightEvent> contacts = Contacts(Basketball, hoop, from, s);
            Assert.That(contacts, Is.Not.Empty);
            Assert.That(contacts[0].ShapeId, Is.EqualTo(11), "off the backboard first");
            Assert.That(contacts[0].State.Position.Z, Is.GreaterThan(3.05), "above the ring");
            foreach (FlightEvent e in contacts)
            {
                Assert.That(e.ShapeId != 10 || e.State.Position.Z < 3.05 - 0.2, Is.True, "the ring is not touched on the way in: " + e);
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ABankShot_FromTheSide_ByBothAngles_AndBySpeed_ReachesTheRimsCentre(bool adaptive)
        {
            ContactShape[] hoop = Hoop();
            var rimCentre = ((TorusShape)hoop[0]).Centre;
            var from = new Vector3d(1, 2.5, 2.2); // off to the side: the bank goes off the board at an angle
            AimSolution both = Solver(Basketball, hoop, adaptive).AnglesToReach(from, 9, LaunchSpin.None, rimCentre, arc: AimArc.High, viaShapeId: 11);
            TestContext.Out.WriteLine(both.ToString());
            Assert.That(both.Status, Is.EqualTo(AimStatus.Solved), both.ToString());
            Assert.That(both.Miss, Is.LessThan(1e-4));
            Assert.That(Contacts(Basketball, hoop, from, both)[0].ShapeId, Is.EqualTo(11));

            var straight = new Vector3d(0, 0, 2.2);
            AimSolution bySpeed = Solver(Basketball, hoop, adaptive).SpeedToReach(straight, 64 * Math.PI / 180, 0, LaunchSpin.None, rimCentre, viaShapeId: 11);
            TestContext.Out.WriteLine(bySpeed.ToString());
            Assert.That(bySpeed.Status, Is.EqualTo(AimStatus.Solved), bySpeed.ToString());
            Assert.That(bySpeed.Miss, Is.LessThan(1e-6));
            Assert.That(Contacts(Basketball, hoop, straight, bySpeed)[0].ShapeId, Is.EqualTo(11));
        }

        [Test]
        public void ShapesAndViaIds_AreChecked()
        {
            Assert.That(() => new AimSolver(Tennis, Ground, shapes: new ContactShape[] { null! }),
                Throws.ArgumentException.With.Property("ParamName").EqualTo("shapes"));
            var target = new Vector3d(21, 0, 0);
            Assert.That(() => Solver(Tennis, Net(), true).ElevationToReach(default, 30, Topspin, target, viaShapeId: 99),
                Throws.ArgumentException.With.Property("ParamName").EqualTo("viaShapeId"));
            Assert.That(() => Solver(Tennis, null, true).SpeedToReach(default, 0.1, 0, Topspin, target, viaShapeId: 0),
                Throws.ArgumentException.With.Property("ParamName").EqualTo("viaShapeId"));
        }

        [Test]
        public void WithoutShapes_AnswersKeepTheirBits()
        {
            var from = new Vector3d(0, 0, 1);
            var target = new Vector3d(21, 2, 0);
            AimSolution a = new AimSolver(Tennis, Ground).AnglesToReach(from, 30, Topspin, target);
            AimSolution b = new AimSolver(Tennis, Ground, shapes: Array.Empty<ContactShape>()).AnglesToReach(from, 30, Topspin, target);
            Assert.That(b.ElevationRadians, Is.EqualTo(a.ElevationRadians));
            Assert.That(b.AzimuthFromTargetRadians, Is.EqualTo(a.AzimuthFromTargetRadians));
            Assert.That(b.Simulations, Is.EqualTo(a.Simulations));
        }
    }
}
