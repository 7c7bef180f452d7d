using System;
using MagnusBall.Aerodynamics;
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

        [Test]
        public void BallCaughtBetweenShapes_EndsAtTheWorkCap_CountingTheTouchSearches()
        {
            // Shape fuzz, finding F3: a 0.74 m ball starting in a box, caught between the box and a cylinder, is held at every step
            // with 16 contacts, each step searching its pieces against both shapes; the cap counted model evaluations and steps only,
            // and the call ran 12,436 steps (31.6 s in Release). The touch searches' pieces now count toward the cap, and the run ends
            // on them long before its evaluations and steps reach it.
            var model = new FlightModel(new Ball(0.3432506102128012, 0.7422106638477507, 0.3903181023617825), Air.SeaLevel,
                new Vector3d(0.5, -0.3, -9.8), StepanekDrag.Instance, StepanekLift.Instance, null);
            var up = new Vector3d(-0.05093033623687437, 0.03055820174212462, 0.9982345902427376);
            var shapes = new ContactShape[]
            {
                new BoxShape(3, new Vector3d(3.070540161836213, -1.8920981077906203, 2.6835410498005996), new Vector3d(0.10853483138506644, 10.917738981672237, 0.43190096679266543),
                    new Vector3d(0.7913870128899394, 0.5426976525611371, -0.2813998111828971), new Vector3d(0.7651556467837296, -0.475344932600987, 0.43426262934488785),
                    new MagnusBall.Contact.ContactProperties(0.42965116139019427, 0.788360850321297, 0, 0.007823035804472415, 0, 0), 3.998884152466079),
                new CylinderShape(4, new Vector3d(-0.016248894397285163, 1.2785412120998565, 0.13464835315693557), new Vector3d(0.12637025435687704, 1.2445361281277663, 0.1668702603053573),
                    0.09802372835790371, new MagnusBall.Contact.ContactProperties(0.05873705216624637, 0.7555218999066958, 0, 0.008256748527407995, 0.0065403175617290265, 0)),
            };
            var predictor = new TrajectoryPredictor(model, Integrators.FromName("stable-rk4"), 0.00028387286924670045, new FlightEventSet(up, new Plane(Vector3d.Zero, up)), shapes);
            Prediction p = predictor.Predict(new FlightState(new Vector3d(-0.7259897008294627, 1.5031010917787435, 0.05535490955124636),
                new Vector3d(-1.320316362795181, -5.022598644225224, -1.2211645076591227), new Vector3d(27.078502602330907, -80.54945086512346, 113.85003268263397), 287.553197838158),
                4.257658458900479, new FlightState[59], new FlightEvent[0], FlightEventKinds.Landing);
            Assert.That(p.WorkLimitReached, Is.True);
            Assert.That(p.DerivativeEvaluations + p.Steps, Is.LessThan(TrajectoryPredictor.MaxEvaluationsPerPrediction / 10), "ended on the searches' work");
        }
    }
}
