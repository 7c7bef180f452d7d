using System;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>
    /// A step far beyond the integrator's stability limit (k C_D s h ~ 30 for a 1e5 m/s tennis ball at
    /// 1/60 s) makes the state overflow. The queries report it instead of returning NaN or throwing mid-solve.
    /// </summary>
    [TestFixture]
    public class DivergenceTests
    {
        private static readonly FlightState Absurd = new FlightState(new Vector3d(0, 0, 1), new Vector3d(1e5, 0, 1e4), default);

        [Test]
        public void Stepper_RefusesADivergingStep_AndKeepsEverything()
        {
            var stepper = new FlightStepper(Shots.StepanekTennis(Gravity.ZUp), RungeKutta4.Instance);
            stepper.Reset(Absurd);
            FlightState last = stepper.State;
            int steps = 0;
            while (stepper.TryStep(1.0 / 60) != StepOutcome.Diverged)
            {
                last = stepper.State;
                Assert.That(++steps, Is.LessThan(1000), "it must diverge");
            }

            Assert.That(stepper.State.IsFinite, Is.True);
            Assert.That(stepper.State.Time, Is.EqualTo(last.Time));

            // One divergence policy: every refused step leaves everything as it was, however often it is asked.
            long evaluations = stepper.DerivativeEvaluations, stepCount = stepper.StepCount;
            Assert.That(stepper.TryStep(1.0 / 60), Is.EqualTo(StepOutcome.Diverged));
            Assert.That(stepper.State, Is.EqualTo(last));
            Assert.That(stepper.DerivativeEvaluations, Is.EqualTo(evaluations));
            Assert.That(stepper.StepCount, Is.EqualTo(stepCount));
        }

        [Test]
        public void Predictor_ReportsDivergence()
        {
            // No ground and no apex: the overshooting steps would otherwise "land" the ball before it overflows.
            var predictor = new TrajectoryPredictor(Shots.StepanekTennis(Gravity.ZUp), RungeKutta4.Instance, 1.0 / 60, new FlightEventSet(Vector3d.Zero));
            Span<Vector3d> line = stackalloc Vector3d[100];
            Prediction p = predictor.Predict(Absurd, 10, line);
            Assert.That(p.Diverged, Is.True);
            Assert.That(p.Stopped, Is.False);
            Assert.That(p.EndState.IsFinite, Is.True);
            for (int i = 0; i < p.SampleCount; i++)
            {
                Assert.That(line[i].IsFinite, Is.True);
            }
        }

        [Test]
        public void Aim_AtAbsurdSpeed_IsUnreachableNotAnException()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var solver = new AimSolver(model, RungeKutta4.Instance, 1.0 / 60, Plane.Ground(model), maximumSpeed: 1e5);
            AimSolution s = solver.ElevationToReach(new Vector3d(0, 0, 1), 1e5, LaunchSpin.None, new Vector3d(20, 0, 0));
            Assert.That(s.Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(double.IsNaN(s.ElevationRadians) || double.IsNaN(s.Speed), Is.False);
        }

        [Test]
        public void AdaptiveAim_AtAbsurdSpeed_EndsWithoutNaNOrException()
        {
            // Adaptive trials do not diverge at 1e5 m/s (their steps shrink instead): whatever the status, the solve ends,
            // within its caps, with finite numbers.
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var solver = new AimSolver(model, Plane.Ground(model), maximumSpeed: 1e5);
            AimSolution s = solver.ElevationToReach(new Vector3d(0, 0, 1), 1e5, LaunchSpin.None, new Vector3d(20, 0, 0));
            TestContext.Out.WriteLine(s.ToString());
            Assert.That(double.IsNaN(s.ElevationRadians) || double.IsNaN(s.Speed) || double.IsNaN(s.Miss), Is.False);
            AimSolution v = solver.SpeedToReach(new Vector3d(0, 0, 1), 0.2, 0, LaunchSpin.None, new Vector3d(20, 0, 0));
            TestContext.Out.WriteLine(v.ToString());
            Assert.That(v.IsSolved, Is.True);
            Assert.That(double.IsFinite(v.Speed), Is.True);
        }
    }
}
