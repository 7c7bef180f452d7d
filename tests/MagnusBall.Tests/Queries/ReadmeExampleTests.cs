using System;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>README's "Where it lands, and how to aim" example, compiled and run.</summary>
    [TestFixture]
    public class ReadmeExampleTests
    {
        [Test]
        public void ReadmeExample_Runs()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            var velocity = new Vector3d(29.7, 0, 4.2);
            var state = new FlightState(new Vector3d(0, 0, 1), velocity, Spin.Topspin(velocity, up: Vector3d.UnitZ, Spin.FromRpm(1200)));

            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240, FlightEventSet.ForModel(model, net));
            Span<Vector3d> line = stackalloc Vector3d[512];
            Prediction p = predictor.Predict(state, maxDuration: 5, line);

            var aim = new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, Plane.Ground(model));
            AimSolution clear = aim.MinimumElevationToClear(new Vector3d(0, 0, 1), 30, 0, new LaunchSpin(topspin: 125.7), net, 0.914);
            if (clear.IsSolved)
            {
                state = clear.LaunchState(new Vector3d(0, 0, 1));
            }

            Assert.That(p.StopEvent.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(clear.IsSolved, Is.True);
            Assert.That(state.Velocity.Length, Is.EqualTo(30).Within(1e-12));
        }

        [Test]
        public void ReadmeFirstSteps_Run()
        {
            // README's first example (one step through IIntegrator, then 239 in one RungeKutta4.Advance call), compiled and run.
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            var velocity = new Vector3d(29.7, 0, 4.2);
            var state = new FlightState(new Vector3d(0, 0, 1), velocity, Spin.Topspin(velocity, up: Vector3d.UnitZ, Spin.FromRpm(1200)));
            IIntegrator rk4 = RungeKutta4.Instance;
            var k1 = model.Derivative(state);
            state = rk4.Step(model, state, k1, 1.0 / 240, out k1, out _);
            int taken = RungeKutta4.Instance.Advance(model, ref state, ref k1, 1.0 / 240, 239);

            Assert.That(taken, Is.EqualTo(239));
            Assert.That(state.Time, Is.EqualTo(1.0).Within(1e-12), "240 steps of 1/240 s");
            Assert.That(state.Position.X, Is.GreaterThan(15).And.LessThan(29.7), "a second of a 29.7 m/s drive, slowed by drag");
        }

        [Test]
        public void DefaultSegment_GivesNoNaN()
        {
            var stepper = new FlightStepper(FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp), RungeKutta4.Instance);
            HermiteSegment none = stepper.LastSegment;
            Assert.That(none.PositionAt(1).IsFinite && none.VelocityAt(1).IsFinite && none.StateAt(1).IsFinite, Is.True);
            Assert.That(none.TryFindCrossing(new Plane(default, Vector3d.UnitZ), CrossingDirection.AgainstNormal, out _), Is.False);
            Assert.That(none.TryFindApex(Vector3d.UnitZ, out _), Is.False);
        }
    }
}
