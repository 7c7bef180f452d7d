using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Flight;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Flight
{
    /// <summary>
    /// A user's law or bounce model that throws inside a call: the call lets its exception through and leaves the flight as
    /// it was, so the next call (once the user's code behaves) is the call a flight that never saw the exception makes.
    /// </summary>
    public class ThrowingUserCodeTests
    {
        private sealed class SwitchableBounce : IBounceModel
        {
            public bool Throw;

            public BounceOutcome Bounce(Ball ball, in Vector3d normal, in Vector3d velocity, in Vector3d angularVelocity)
            {
                if (Throw)
                {
                    throw new InvalidOperationException("the user's bounce model failed");
                }

                return CrossBounce.Hard.Bounce(ball, normal, velocity, angularVelocity);
            }
        }

        private static readonly FlightState Launch = new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 0, 3), new Vector3d(0, 80, 0));

        private static (FlightStepper Stepper, SwitchableDrag Drag, SwitchableBounce Bounce) Flight()
        {
            var drag = new SwitchableDrag();
            var bounce = new SwitchableBounce();
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, drag);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model), new GroundContact(bounce, Plane.Ground(model)));
            stepper.Reset(Launch);
            return (stepper, drag, bounce);
        }

        private static void AssertUnchanged(FlightStepper stepper, FlightStepper twin)
        {
            Assert.That(stepper.State, Is.EqualTo(twin.State), "state");
            Assert.That(stepper.PreviousState, Is.EqualTo(twin.PreviousState), "previous state");
            double mid = 0.5 * (twin.PreviousState.Time + twin.State.Time);
            Assert.That(stepper.StateAt(mid), Is.EqualTo(twin.StateAt(mid)), "StateAt inside the last step");
            Assert.That(stepper.DerivativeEvaluations, Is.EqualTo(twin.DerivativeEvaluations), "evaluations");
            Assert.That(stepper.StepCount, Is.EqualTo(twin.StepCount), "steps");
            Assert.That(stepper.BounceCount, Is.EqualTo(twin.BounceCount), "bounces");
            Assert.That(stepper.Events.Length, Is.EqualTo(twin.Events.Length), "events");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ALawThrowingInsideAStep_LeavesTheFlightAsItWas(bool adaptive)
        {
            var (stepper, drag, _) = Flight();
            var (twin, _, _) = Flight();
            for (int i = 0; i < 3; i++)
            {
                Step(stepper, adaptive);
                Step(twin, adaptive);
            }

            drag.Throw = true;
            Assert.Throws<InvalidOperationException>(() => Step(stepper, adaptive));
            AssertUnchanged(stepper, twin);

            drag.Throw = false;
            Assert.That(Step(stepper, adaptive), Is.EqualTo(Step(twin, adaptive)));
            AssertUnchanged(stepper, twin);
        }

        [Test]
        public void ABounceModelThrowingAtTheContact_LeavesTheFlightAsItWas()
        {
            var (stepper, _, bounce) = Flight();
            var (twin, _, _) = Flight();
            // Fly both to the step before the first bounce.
            while (true)
            {
                var (probe, _, _) = Flight();
                for (long i = 0; i < twin.StepCount; i++)
                {
                    probe.TryStep(0.01);
                }

                probe.TryStep(0.01);
                if (probe.BounceCount > 0)
                {
                    break;
                }

                Assert.That(twin.StepCount, Is.LessThan(1000), "the ball reaches the ground");
                stepper.TryStep(0.01);
                twin.TryStep(0.01);
            }

            bounce.Throw = true;
            Assert.Throws<InvalidOperationException>(() => stepper.TryStep(0.01));
            AssertUnchanged(stepper, twin);

            bounce.Throw = false;
            Assert.That(stepper.TryStep(0.01), Is.EqualTo(twin.TryStep(0.01)));
            Assert.That(stepper.BounceCount, Is.EqualTo(1));
            AssertUnchanged(stepper, twin);
        }

        [Test]
        public void ALawThrowingInSetState_LeavesTheFlightAsItWas()
        {
            var (stepper, drag, _) = Flight();
            var (twin, _, _) = Flight();
            stepper.TryStep(0.01);
            twin.TryStep(0.01);
            drag.Throw = true;
            var hit = new FlightState(stepper.State.Position, new Vector3d(-15, 0, 4), default, stepper.State.Time);
            Assert.Throws<InvalidOperationException>(() => stepper.SetState(hit));
            Assert.Throws<InvalidOperationException>(() => stepper.Reset(Launch));
            AssertUnchanged(stepper, twin);
        }

        private static StepOutcome Step(FlightStepper stepper, bool adaptive) =>
            adaptive ? stepper.TryStepAdaptive(DormandPrince54.Instance, 0.01) : stepper.TryStep(0.01);
    }
}
