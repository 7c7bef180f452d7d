using System;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Flight
{
    using MagnusBall.Flight;

    /// <summary>
    /// The one flight core: its counters count real model calls, a bounce step still reports its apex and plane
    /// crossings, events work on adaptive steps, and a refused step changes nothing.
    /// </summary>
    [TestFixture]
    public class FlightCoreTests
    {
        private static FlightModel CountedTennis(out EvaluationCount calls)
        {
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            calls = new EvaluationCount();
            model.CountedEvaluations = calls;
            return model;
        }

        [Test]
        public void StableRk4ThroughTheDriver_MakesExactlyTheEvaluationsItReports_FourPerStep()
        {
            // The driver's default integrator. At 1/240 s a tennis drive never substeps (h sigma ~ 0.003), so each step is
            // exactly one RK4 step: 4 calls of the model (k2, k3, k4 and the end derivative, the next step's k1).
            FlightModel model = CountedTennis(out EvaluationCount calls);
            var driver = new FixedStepDriver(model, 1.0 / 240, Shots.ZUpDrive(new Vector3d(0, 150, 0)));
            Assert.That(driver.Integrator, Is.SameAs(StableIntegrator.RungeKutta4));
            long startCalls = calls.Calls;
            Assert.That(startCalls, Is.EqualTo(1), "Reset evaluates the start derivative once");
            for (int frame = 0; frame < 600 && !driver.IsFinished; frame++)
            {
                driver.Advance(1.0 / 60);
            }

            Assert.That(driver.IsFinished, Is.True);
            Assert.That(driver.DerivativeEvaluations, Is.EqualTo(calls.Calls), "the counter is the number of real calls");
            Assert.That(calls.Calls, Is.EqualTo(1 + 4 * driver.TotalSteps), "4 per step, nothing wasted");
        }

        [TestCase("euler")]
        [TestCase("semi-implicit-euler")]
        [TestCase("heun")]
        [TestCase("rk4")]
        [TestCase("dp54")]
        [TestCase("stable-rk4")]
        public void EveryIntegrator_CountsRealCalls_ThroughThePredictorAndWithBounces(string name)
        {
            IIntegrator integrator = Integrators.FromName(name);
            FlightModel model = CountedTennis(out EvaluationCount calls);
            var stepper = new FlightStepper(model, integrator, FlightEventSet.ForModel(model), new GroundContact(CrossBounce.Hard, Plane.Ground(model)));
            stepper.Reset(Shots.ZUpDrive(new Vector3d(0, 150, 0)));
            for (int i = 0; i < 240 * 20 && !stepper.IsStopped; i++)
            {
                Assert.That(stepper.TryStep(1.0 / 240), Is.Not.EqualTo(StepOutcome.Diverged));
            }

            Assert.That(stepper.BounceCount, Is.GreaterThan(1), "it bounces");
            Assert.That(stepper.DerivativeEvaluations, Is.EqualTo(calls.Calls));
        }

        [Test]
        public void ABounceStep_ReportsItsApexAndPlaneCrossings_InTimeOrder()
        {
            // One 1 s step holds it all: a drop from 1 m lands after ~0.45 s, the ball leaves the court at ~3 m/s and tops out
            // ~0.3 s later; slowed to 2.75 m/s by the grip, it crosses x = 3.5 m at ~0.9 s, after the bounce.
            FlightModel model = FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp);
            var wall = new Plane(new Vector3d(3.5, 0, 0), Vector3d.UnitX);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model, wall), new GroundContact(CrossBounce.Hard, Plane.Ground(model)));
            stepper.Reset(new FlightState(new Vector3d(0, 0, 1), new Vector3d(5, 0, 0), Vector3d.Zero));
            Assert.That(stepper.TryStep(1.0), Is.EqualTo(StepOutcome.Taken));

            FlightEvent[] events = stepper.Events.ToArray(); // a copy: Mono 6.8 cannot index a ReadOnlySpan (docs/determinism.md)
            foreach (FlightEvent e in events)
            {
                TestContext.Out.WriteLine(e.ToString());
            }

            Assert.That(stepper.TryGetEvent(FlightEventKinds.Bounce, out FlightEvent bounce), Is.True);
            Assert.That(stepper.TryGetEvent(FlightEventKinds.Apex, out FlightEvent apex), Is.True, "the apex after the bounce");
            Assert.That(stepper.TryGetEvent(FlightEventKinds.PlaneCrossing, out FlightEvent crossing), Is.True, "the crossing after the bounce");
            Assert.That(apex.Time, Is.GreaterThan(bounce.Time));
            Assert.That(crossing.Time, Is.GreaterThan(bounce.Time));
            Assert.That(crossing.Position.X, Is.EqualTo(3.5).Within(1e-9));
            Assert.That(stepper.TryGetEvent(FlightEventKinds.Landing, out _), Is.False, "with a contact, touching the court is a bounce");
            for (int i = 1; i < events.Length; i++)
            {
                Assert.That(events[i].Time, Is.GreaterThanOrEqualTo(events[i - 1].Time), events[i].ToString());
            }

            // In vacuum the apex is where the vertical speed is zero: its height from the bounce's outgoing speed.
            double vz = bounce.After.Velocity.Z, radius = Ball.Tennis.Radius;
            // 1e-9 m: the apex is located to 1e-12 s on RK4's cubic, exact for this quadratic motion up to rounding.
            Assert.That(apex.Position.Z, Is.EqualTo(radius + vz * vz / (2 * Gravity.Standard)).Within(1e-9));
        }

        [Test]
        public void AdaptiveSteps_FindTheLanding_OnTheirOwnInterpolant()
        {
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            FlightState start = Shots.ZUpDrive(new Vector3d(0, 150, 0));
            var adaptive = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model));
            adaptive.Reset(start);
            var method = new DormandPrince54(1e-10, 1e-10);
            for (int i = 0; i < 10_000 && !adaptive.IsStopped; i++)
            {
                Assert.That(adaptive.TryStepAdaptive(method, 1.0, FlightEventKinds.Landing), Is.Not.EqualTo(StepOutcome.Diverged));
            }

            Assert.That(adaptive.IsStopped, Is.True);
            Vector3d reference = Shots.Landing(model, RungeKutta4.Instance, start, Vector3d.UnitZ, 1.0 / 4000);
            TestContext.Out.WriteLine($"adaptive: {adaptive.StepCount} steps, {adaptive.DerivativeEvaluations} evaluations; landing off by {Vector3d.Distance(adaptive.StopEvent.Position, reference):E2} m");
            // 1e-6 m: at tolerance 1e-10 the adaptive flight and RK4 at 1/4000 s (error ~1e-12 m) agree far better than this;
            // the bound leaves room for the quartic interpolant's own error over steps of ~0.05 s.
            Assert.That(Vector3d.Distance(adaptive.StopEvent.Position, reference), Is.LessThan(1e-6));
            Assert.That(adaptive.StepCount, Is.LessThan(200), "far fewer steps than the fixed grid");
        }

        [Test]
        public void AClockThatCannotAdvance_IsNotADivergence_AndChangesNothing()
        {
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model));
            FlightState start = Shots.ZUpDrive(Vector3d.Zero);
            stepper.Reset(new FlightState(start.Position, start.Velocity, start.AngularVelocity, 1e17));
            FlightState before = stepper.State;
            Assert.That(stepper.TryStep(1.0 / 240), Is.EqualTo(StepOutcome.TimeCannotAdvance));
            Assert.That(stepper.State, Is.EqualTo(before));
            Assert.That(stepper.StepCount, Is.EqualTo(0));
            Assert.That(stepper.DerivativeEvaluations, Is.EqualTo(1));
        }

        [Test]
        public void AStepRefusedAfterABounce_LeavesTheLastStepsEventsAndPiecesAsTheyWere()
        {
            // A bounce that launches the ball at 1e200 m/s: the piece after it overflows, so the step is refused after it
            // already located the apex... and the bounce. Nothing of that half-done step may show.
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model), new GroundContact(new Catapult(), Plane.Ground(model)));
            stepper.Reset(new FlightState(new Vector3d(0, 0, 1), new Vector3d(10, 0, 3), Vector3d.Zero));
            Assert.That(stepper.TryStep(0.35), Is.EqualTo(StepOutcome.Taken), "up to just past the apex (~0.3 s), before the bounce");
            FlightEvent[] events = stepper.Events.ToArray();
            Assert.That(events, Has.Length.EqualTo(1), "the apex");
            HermiteSegment last = stepper.LastSegment;
            FlightState state = stepper.State;

            Assert.That(stepper.TryStep(1.0), Is.EqualTo(StepOutcome.Diverged), "it bounces, then the catapulted piece overflows");
            Assert.That(stepper.Events.ToArray(), Is.EqualTo(events));
            Assert.That(stepper.LastSegment.Start, Is.EqualTo(last.Start));
            Assert.That(stepper.LastSegment.End, Is.EqualTo(last.End));
            Assert.That(stepper.State, Is.EqualTo(state));
            Assert.That(stepper.BounceCount, Is.EqualTo(0));
            Assert.That(stepper.StateAt(state.Time - 0.1), Is.EqualTo(last.StateAt(state.Time - 0.1)));
        }

        /// <summary>A bounce law that sends the ball off the surface at 1e200 m/s.</summary>
        private sealed class Catapult : IBounceModel
        {
            public BounceOutcome Bounce(Ball ball, in Vector3d normal, in Vector3d velocity, in Vector3d angularVelocity) =>
                new BounceOutcome(normal * 1e200, angularVelocity, BounceRegime.Slide, 1, -Vector3d.Dot(velocity, normal));
        }

        [Test]
        public void SteppingAllocatesNothing_WithEventsAndBounces()
        {
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var stepper = new FlightStepper(model, StableIntegrator.RungeKutta4, FlightEventSet.ForModel(model, net), new GroundContact(CrossBounce.Clay, Plane.Ground(model)));
            FlightState start = Shots.ZUpDrive(new Vector3d(0, 200, 0));
            int events = 0;
            Action fly = () => events = Fly(stepper, start); // Fly resets the stepper to the start
            Assert.That(Allocation.SteadyStateBytes(fly), Is.EqualTo(0));
            Assert.That(events, Is.GreaterThan(4), "net, apex, bounces, rest");
        }

        private static int Fly(FlightStepper stepper, in FlightState start)
        {
            stepper.Reset(start);
            int events = 0;
            for (int i = 0; i < 240 * 30 && !stepper.IsStopped; i++)
            {
                stepper.TryStep(1.0 / 240);
                events += stepper.Events.Length;
            }

            return events;
        }
    }
}
