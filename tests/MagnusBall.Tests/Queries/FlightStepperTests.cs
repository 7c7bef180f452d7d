using System;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>The shared stepping loop: counts, allocation, bad input.</summary>
    [TestFixture]
    public class FlightStepperTests
    {
        [TestCaseSource(typeof(Integrators), nameof(Integrators.All))]
        public void Counts_StepsAndDerivativeEvaluations(IIntegrator integrator)
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var stepper = new FlightStepper(model, integrator, FlightEventSet.ForModel(model));
            stepper.Reset(EventLocationTests.TennisDrive(Vector3d.UnitZ));
            for (int i = 0; i < 10; i++)
            {
                stepper.TryStep(0.01);
            }

            Assert.That(stepper.StepCount, Is.EqualTo(10));
            Assert.That(stepper.DerivativeEvaluations, Is.EqualTo(1 + 10 * integrator.DerivativeEvaluationsPerStep));
        }

        [Test]
        public void SteppingWithEvents_AllocatesNothing()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(1, 2, 0)), Gravity.ZUp,
                StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(5));
            var planes = new[] { new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX), new Plane(new Vector3d(20, 0, 0), Vector3d.UnitX) };
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model, planes));
            FlightState start = EventLocationTests.TennisDrive(Vector3d.UnitZ);

            int Fly()
            {
                int events = 0;
                stepper.Reset(start);
                for (int i = 0; i < 200; i++)
                {
                    stepper.TryStep(1.0 / 120);
                    events += stepper.Events.Length;
                }

                return events;
            }

            int count = 0;
            Action fly = () => count = Fly(); // Fly resets the stepper to the start
            long allocated = Allocation.SteadyStateBytes(fly);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(count, Is.GreaterThanOrEqualTo(4), "apex, two planes and a landing happened");
        }

        [Test]
        public void BadInput_IsRejectedBeforeAnyChange()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var stepper = new FlightStepper(model, RungeKutta4.Instance);
            Assert.Throws<InvalidOperationException>(() => stepper.TryStep(0.01));
            FlightState start = EventLocationTests.TennisDrive(Vector3d.UnitZ);
            stepper.Reset(start);
            var ex = Assert.Throws<ArgumentOutOfRangeException>(() => stepper.TryStep(double.NaN));
            Assert.That(ex!.ParamName, Is.EqualTo("step"));
            Assert.Throws<ArgumentOutOfRangeException>(() => stepper.TryStep(0));
            Assert.Throws<ArgumentException>(() => stepper.Reset(new FlightState(new Vector3d(double.NaN, 0, 0), default, default)));
            Assert.That(stepper.State.Position, Is.EqualTo(start.Position));
            Assert.That(stepper.StepCount, Is.EqualTo(0));

            Assert.Throws<ArgumentException>(() => new Plane(default, default));
            Assert.Throws<ArgumentException>(() => new Plane(default, new Vector3d(0, double.PositiveInfinity, 0)));
            Assert.Throws<ArgumentException>(() => Plane.Ground(FlightModel.Vacuum(Ball.Tennis, Vector3d.Zero)));
            Assert.Throws<ArgumentException>(() => new FlightEventSet(Vector3d.UnitZ, new Plane()));
            Assert.Throws<ArgumentException>(() => new HermiteSegment(start, default, start, default));
            var set = FlightEventSet.ForModel(model);
            Assert.Throws<ArgumentException>(() => set.Scan(default, new FlightEvent[1]));
        }
    
        [Test]
        public void SetNextAdaptiveStep_SetsTheFirstStep_AndSavesTheGuessesEvaluation()
        {
            // Counted by the model itself. After Reset (one evaluation), an adaptive step from InitialStep's guess costs that
            // guess's evaluation and six; with the step set, six, and the step taken is the one set. Values that are not
            // finite and positive are ignored (the guess is used).
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, MagnusBall.Aerodynamics.StepanekDrag.Instance);
            var calls = new EvaluationCount();
            model.CountedEvaluations = calls;
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 0, 3), new Vector3d(0, 60, 0));
            var stepper = new FlightStepper(model, RungeKutta4.Instance);
            var method = new DormandPrince54(1e-8, 1e-8);
            foreach (double ignored in new[] { 0, -0.01, double.NaN, double.PositiveInfinity })
            {
                stepper.Reset(start);
                stepper.SetNextAdaptiveStep(ignored);
                long before = calls.Calls;
                Assert.That(stepper.TryStepAdaptive(method, 1.0), Is.EqualTo(StepOutcome.Taken));
                Assert.That(calls.Calls - before, Is.EqualTo(7), $"{ignored}: the guess's evaluation and one step");
            }

            stepper.Reset(start);
            stepper.SetNextAdaptiveStep(0.01);
            long at = calls.Calls;
            Assert.That(stepper.TryStepAdaptive(method, 1.0), Is.EqualTo(StepOutcome.Taken));
            Assert.That(calls.Calls - at, Is.EqualTo(6));
            Assert.That(stepper.CurrentTime, Is.EqualTo(0.01));
            Assert.That(stepper.LastAdaptiveStep.Step, Is.EqualTo(0.01));

            // Still capped by the call's maximum.
            stepper.Reset(start);
            stepper.SetNextAdaptiveStep(0.01);
            Assert.That(stepper.TryStepAdaptive(method, 0.004), Is.EqualTo(StepOutcome.Taken));
            Assert.That(stepper.CurrentTime, Is.EqualTo(0.004));
        }
}
}
