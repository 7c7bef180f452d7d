using System;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>The predictor flies among shapes as the flight core does: a drive into the net is stopped by it, reported.</summary>
    public class PredictorShapesTests
    {
        [Test]
        public void DriveIntoTheNet_IsAContactWithTheNet_AndDoesNotCrossIt()
        {
            FlightModel model = SportPresets.Tennis.CreateModel(Air.SeaLevel, Gravity.ZUp);
            ContactShape[] net = SportShapes.TennisNet(10, new Vector3d(11.885, 0, 0), Vector3d.UnitY, Vector3d.UnitZ);
            // 25 m/s at 3 degrees from 1 m up, no spin: about 0.45 m up when it reaches the net line, under the 0.914 m cord.
            double e = 3 * Math.PI / 180;
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(25 * Math.Cos(e), 0, 25 * Math.Sin(e)), Vector3d.Zero);
            var events = new FlightEvent[16];

            Prediction free = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240).Predict(start, 3, Span<FlightState>.Empty, events);
            Assert.That(free.EndState.Position.X, Is.GreaterThan(11.885), "without the net it flies through the net's line");

            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240, shapes: net);
            Prediction blocked = predictor.Predict(start, 3, Span<FlightState>.Empty, events);
            int contact = Array.FindIndex(events, 0, blocked.EventCount, ev => ev.Kind == FlightEventKinds.Contact);
            Assert.That(contact, Is.GreaterThanOrEqualTo(0), "a contact event");
            Assert.That(events[contact].ShapeId, Is.InRange(10, 14), "with one of the net's shapes");
            // The mesh is the net's plane with no thickness: the centre touches one radius before it. 1e-9 m: the contact is
            // located to 1e-12 s, 2.5e-11 m at 25 m/s, with room for the position's rounding.
            Assert.That(events[contact].Position.X, Is.EqualTo(11.885 - model.Ball.Radius).Within(1e-9), "at the net, one radius before its plane");
            Assert.That(events[contact].ContactNormal.X, Is.EqualTo(-1).Within(1e-12), "the mesh's normal faces the ball");
            Assert.That(blocked.EndState.Position.X, Is.LessThan(11.885), "and the ball stays on its side");
            Assert.Throws<ArgumentException>(() => new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240, shapes: new ContactShape[] { null! }));
        }
    }
}
