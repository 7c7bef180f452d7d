using System;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    [TestFixture]
    public class TrajectoryPredictorTests
    {
        private static FlightModel Model => Shots.StepanekTennis(Gravity.ZUp);

        [Test]
        public void Samples_AreTheStepsAndEndAtTheLanding()
        {
            FlightModel model = Model;
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 60);
            FlightState start = EventLocationTests.TennisDrive(Vector3d.UnitZ);
            var samples = new FlightState[200];
            var events = new FlightEvent[8];
            Prediction p = predictor.Predict(start, 10, samples, events);

            Assert.That(p.Stopped, Is.True);
            Assert.That(p.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(p.EndState.Position.Z, Is.EqualTo(0).Within(1e-9));
            Assert.That(p.SampleCount, Is.EqualTo(p.Steps + 1), "start, each step but the last, and the landing");
            Assert.That(samples[0].Position, Is.EqualTo(start.Position));
            Assert.That(samples[p.SampleCount - 1].Time, Is.EqualTo(p.EndState.Time));
            Assert.That(p.DerivativeEvaluations, Is.EqualTo(1 + 4 * p.Steps));
            Assert.That(p.SamplesTruncated || p.EventsTruncated, Is.False);

            // The same flight stepped by hand passes through the same points.
            FlightState byHand = Shots.Fly(model, RungeKutta4.Instance, start, 1.0 / 60, 10);
            Assert.That(samples[10].Position, Is.EqualTo(byHand.Position));

            // Events: the apex, then the landing, in time order.
            Assert.That(p.EventCount, Is.EqualTo(2));
            Assert.That(events[0].Kind, Is.EqualTo(FlightEventKinds.Apex));
            Assert.That(events[1].Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(events[0].Time, Is.LessThan(events[1].Time));
        }

        [Test]
        public void SmallBuffer_IsTruncatedButTheFlightStillEnds()
        {
            var predictor = new TrajectoryPredictor(Model, RungeKutta4.Instance, 1.0 / 60);
            Span<Vector3d> positions = stackalloc Vector3d[5];
            Prediction p = predictor.Predict(EventLocationTests.TennisDrive(Vector3d.UnitZ), 10, positions);
            Assert.That(p.SampleCount, Is.EqualTo(5));
            Assert.That(p.SamplesTruncated, Is.True);
            Assert.That(p.Stopped, Is.True);
            Assert.That(p.EndState.Position.X, Is.GreaterThan(20));
        }

        [Test]
        public void TimeLimit_EndsExactlyThere()
        {
            var predictor = new TrajectoryPredictor(Model, RungeKutta4.Instance, 0.01);
            FlightState start = EventLocationTests.TennisDrive(Vector3d.UnitZ);
            Prediction p = predictor.Predict(start, 0.255, Span<Vector3d>.Empty, FlightEventKinds.None);
            Assert.That(p.Stopped, Is.False);
            Assert.That(p.Steps, Is.EqualTo(26));
            Assert.That(p.EndState.Time, Is.EqualTo(0.255).Within(1e-15));
        }

        [Test]
        public void StopAtPlane_StopsAtTheNet()
        {
            FlightModel model = Model;
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 120, FlightEventSet.ForModel(model, net));
            Prediction p = predictor.Predict(EventLocationTests.TennisDrive(Vector3d.UnitZ), 10, Span<Vector3d>.Empty, FlightEventKinds.PlaneCrossing);
            Assert.That(p.StopEvent.Kind, Is.EqualTo(FlightEventKinds.PlaneCrossing));
            Assert.That(p.StopEvent.PlaneIndex, Is.EqualTo(0));
            Assert.That(p.EndState.Position.X, Is.EqualTo(11.885).Within(1e-9));
        }

        [Test]
        public void Predict_AllocatesNothing()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(2, 1, 0)), Gravity.ZUp,
                StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(5));
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240,
                FlightEventSet.ForModel(model, new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX)));
            FlightState start = EventLocationTests.TennisDrive(Vector3d.UnitZ);
            var samples = new FlightState[1000];
            var events = new FlightEvent[8];
            var positions = new Vector3d[1000];

            Prediction a = default, b = default;
            Action predict = () =>
            {
                a = predictor.Predict(start, 10, samples, events);
                b = predictor.Predict(start, 10, positions, FlightEventKinds.All);
            };

            long allocated = Allocation.SteadyStateBytes(predict);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(a.Stopped && b.Stopped, Is.True);
        }

        [Test]
        public void BadInput_NamesTheParameter()
        {
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new TrajectoryPredictor(Model, RungeKutta4.Instance, 0))!.ParamName, Is.EqualTo("step"));
            var predictor = new TrajectoryPredictor(Model, RungeKutta4.Instance, 0.01);
            FlightState start = EventLocationTests.TennisDrive(Vector3d.UnitZ);
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => predictor.Predict(start, double.NaN, Span<Vector3d>.Empty))!.ParamName, Is.EqualTo("maxDuration"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => predictor.Predict(start, -1, Span<Vector3d>.Empty))!.ParamName, Is.EqualTo("maxDuration"));
            var bad = new FlightState(start.Position, new Vector3d(double.PositiveInfinity, 0, 0), default);
            Assert.That(Assert.Throws<ArgumentException>(() => predictor.Predict(bad, 1, Span<Vector3d>.Empty))!.ParamName, Is.EqualTo("state"));
        }
    }
}
