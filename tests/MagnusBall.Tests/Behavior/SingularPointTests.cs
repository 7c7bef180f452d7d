using MagnusBall.Aerodynamics;
using NUnit.Framework;

namespace MagnusBall.Tests.Behavior
{
    /// <summary>Points where a naive Magnus formula divides by zero give finite, correct answers.</summary>
    [TestFixture]
    public class SingularPointTests
    {
        private static readonly FlightModel Full = new FlightModel(
            Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(4));

        [Test]
        public void SpinParallelToVelocity_GivesExactlyTheDragOnlyAcceleration()
        {
            var velocity = new Vector3d(20, 5, 3);
            var spin = velocity.NormalizedOrZero() * 400; // pure "gyro" spin along the flight
            var state = new FlightState(new Vector3d(0, 0, 1), velocity, spin);
            // The general formula: the lift's term is exactly nothing.
            Assert.That(Full.GeneralDerivative(state).Acceleration, Is.EqualTo(Full.WithLift(null).GeneralDerivative(state).Acceleration));
            // The flight kernel computes this model's drag and lift in a folded form (equal to the formula to rounding,
            // FlightKernelTests.FoldedStepanekLift_EqualsTheGeneralFormula_ToRounding): there the lift's term is nothing either,
            // and the acceleration is the drag-only one within that rounding (1e-15 of |g| + |drag|, about 4.5 ulp).
            StateDerivative withLift = Full.Derivative(state);
            StateDerivative dragOnly = Full.WithLift(null).Derivative(state);
            double scale = Gravity.ZUp.Length + (dragOnly.Acceleration - Gravity.ZUp).Length;
            Assert.That((withLift.Acceleration - dragOnly.Acceleration).Length, Is.LessThanOrEqualTo(1e-15 * scale));
        }

        [Test]
        public void ExactlyAntiParallelAxisSpin_GivesNoMagnusForce()
        {
            var state = new FlightState(Vector3d.Zero, new Vector3d(0, 0, -12), new Vector3d(0, 0, 300));
            StateDerivative d = Full.Derivative(state);
            Assert.That(d.Acceleration.X, Is.EqualTo(0));
            Assert.That(d.Acceleration.Y, Is.EqualTo(0));
            Assert.That(d.Acceleration.IsFinite, Is.True);
        }

        [Test]
        public void BallAtRestWithSpin_HasGravityOnly_AndNoNaN()
        {
            var state = new FlightState(new Vector3d(1, 2, 3), Vector3d.Zero, new Vector3d(100, -50, 20));
            StateDerivative d = Full.Derivative(state);
            Assert.That(d.Acceleration, Is.EqualTo(Gravity.ZUp));
            Assert.That(d.AngularAcceleration.IsFinite, Is.True);
            Assert.That(d.Velocity, Is.EqualTo(Vector3d.Zero));
        }

        [Test]
        public void NoSpin_GivesNoLift_AndNoNaN()
        {
            var state = new FlightState(Vector3d.Zero, new Vector3d(30, 0, 0), Vector3d.Zero);
            StateDerivative d = Full.Derivative(state);
            Assert.That(d.Acceleration.Y, Is.EqualTo(0));
            Assert.That(d.Acceleration.Z, Is.EqualTo(-Gravity.Standard));
            Assert.That(d.Acceleration.X, Is.LessThan(0));
        }

        [Test]
        public void BallMovingExactlyWithTheWind_FeelsNoAerodynamicForce()
        {
            var wind = new Vector3d(7, -3, 0);
            FlightModel windy = Full.WithAir(new Air(1.21, wind));
            var state = new FlightState(Vector3d.Zero, wind, new Vector3d(0, 0, 250));
            StateDerivative d = windy.Derivative(state);
            Assert.That(d.Acceleration, Is.EqualTo(Gravity.ZUp));
        }

        [Test]
        public void DragUsesTheAirRelativeVelocity()
        {
            // A ball at rest in a headwind is pushed downwind.
            FlightModel windy = Full.WithAir(new Air(1.21, new Vector3d(-10, 0, 0)));
            StateDerivative d = windy.Derivative(new FlightState(Vector3d.Zero, Vector3d.Zero, Vector3d.Zero));
            Assert.That(d.Acceleration.X, Is.LessThan(0));
        }

        [Test]
        public void LinearSpinLift_AtAVanishingSpeed_StaysFinite()
        {
            FlightModel model = Full.WithLift(LinearSpinLift.Cross2020Tennis);
            foreach (double speed in new[] { 1e-300, 1e-160, 1e-20, 1e-3 })
            {
                StateDerivative d = model.Derivative(new FlightState(Vector3d.Zero, new Vector3d(speed, 0, 0), new Vector3d(0, 1000, 0)));
                Assert.That(d.Acceleration.IsFinite && d.AngularAcceleration.IsFinite, Is.True, $"speed {speed}");
            }
        }

        [Test]
        public void TransverseSpinForm_EqualsTheThesisForm_WhenSpinIsPerpendicular()
        {
            // Thesis eq. 2: F = 1/2 C_M rho A s^2 (w x v)/|w x v|, for w perpendicular to v.
            FlightModel thesis = new FlightModel(Ball.Tennis, new Air(1.29), Vector3d.Zero, null, ConstantLift.ThesisTennis);
            var velocity = new Vector3d(25, 0, 4);
            Vector3d spin = Spin.Topspin(velocity, Vector3d.UnitZ, 125.7);
            StateDerivative d = thesis.Derivative(new FlightState(Vector3d.Zero, velocity, spin));
            Vector3d cross = Vector3d.Cross(spin, velocity);
            Vector3d expected = cross / cross.Length * (0.5 * 0.175 * 1.29 * Ball.Tennis.CrossSectionalArea * velocity.LengthSquared / Ball.Tennis.Mass);
            Assert.That(Vector3d.Distance(d.Acceleration, expected), Is.LessThan(1e-12));
        }
    }
}
