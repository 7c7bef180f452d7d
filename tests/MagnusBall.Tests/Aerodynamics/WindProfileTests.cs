using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Aerodynamics
{
    /// <summary>The logarithmic wind profile and the air-relative velocity the flight model builds from it.</summary>
    [TestFixture]
    public class WindProfileTests
    {
        private static readonly Vector3d Breeze = new Vector3d(5, 0, 0);

        [Test]
        public void Factor_IsOneAtTheReferenceHeight_ZeroAtAndBelowZ0_LogarithmicBetween()
        {
            var profile = new LogarithmicWindProfile(10, 0.03);
            Assert.That(profile.Factor(10), Is.EqualTo(1).Within(1e-15));
            Assert.That(profile.Factor(0.03), Is.EqualTo(0));
            Assert.That(profile.Factor(-5), Is.EqualTo(0));
            Assert.That(profile.Factor(1), Is.EqualTo(Math.Log(1 / 0.03) / Math.Log(10 / 0.03)).Within(1e-15));
            // Continuous at z0: just above it the factor is ln(1 + 1e-9)/ln(333) ~ 1.7e-10.
            Assert.That(profile.Factor(0.03 * (1 + 1e-9)), Is.LessThan(1e-9));
        }

        [Test]
        public void WindAt_MeasuresHeightAlongUpFromTheGroundPoint_InAnyFrame()
        {
            Air zUp = Air.SeaLevel.WithLogarithmicWind(Breeze, 10, 0.03, new Vector3d(0, 0, 2));
            Air yUp = Air.SeaLevel.WithLogarithmicWind(Breeze, 10, 0.03, new Vector3d(0, 2, 0));
            Vector3d atZ = zUp.WindAt(new Vector3d(100, -40, 3), Vector3d.UnitZ);
            Vector3d atY = yUp.WindAt(new Vector3d(100, 3, -40), Vector3d.UnitY);
            double expected = 5 * Math.Log(1 / 0.03) / Math.Log(10 / 0.03);
            Assert.That(atZ.X, Is.EqualTo(expected).Within(1e-12));
            Assert.That(atY.X, Is.EqualTo(expected).Within(1e-12));
            // Uniform air, and a profile without an up direction, give the reference wind everywhere.
            Assert.That(Air.SeaLevel.WithWind(Breeze).WindAt(new Vector3d(0, 0, 50), Vector3d.UnitZ), Is.EqualTo(Breeze));
            Assert.That(zUp.WindAt(new Vector3d(0, 0, 50), Vector3d.Zero), Is.EqualTo(Breeze));
        }

        [Test]
        public void UniformWind_GivesTheSameDerivativeAsBefore()
        {
            // The uniform path must be exactly v - wind, as the core computed it.
            var air = new Air(1.21, new Vector3d(3, -2, 0.5));
            var model = new FlightModel(Ball.Tennis, air, Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            var state = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            var stillModel = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            // Galilean check: in still air, a ball moving at v - wind feels the same force.
            var shifted = new FlightState(state.Position, state.Velocity - air.Wind, state.AngularVelocity);
            Assert.That(model.Derivative(state).Acceleration, Is.EqualTo(stillModel.Derivative(shifted).Acceleration));
        }

        [Test]
        public void ProfileWind_UsesTheAirRelativeVelocityForDragLiftAndSpinDecay()
        {
            // A spinning ball moving exactly with the local wind feels no aerodynamic force and, with a
            // speed-proportional decay law, loses no spin: every term reads the same air-relative velocity.
            Air air = Air.SeaLevel.WithLogarithmicWind(Breeze, 10, 0.03);
            var model = new FlightModel(Ball.Tennis, air, Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance,
                SpeedProportionalSpinDecay.TennisCrossLindsey);
            var position = new Vector3d(0, 0, 3);
            Vector3d local = air.WindAt(position, Vector3d.UnitZ);
            StateDerivative d = model.Derivative(new FlightState(position, local, new Vector3d(0, 200, 0)));
            Assert.That(d.Acceleration, Is.EqualTo(Gravity.ZUp));
            Assert.That(d.AngularAcceleration, Is.EqualTo(Vector3d.Zero));

            // At another height the same ground velocity meets another wind: the force changes.
            StateDerivative higher = model.Derivative(new FlightState(new Vector3d(0, 0, 20), local, new Vector3d(0, 200, 0)));
            // At 20 m the wind (5.6 m/s) outruns the ball (3.96 m/s): drag pushes the ball downwind (+x).
            Assert.That(higher.Acceleration.X, Is.GreaterThan(0));
        }

        [Test]
        public void ProfileWind_SteppingAllocatesZeroBytes()
        {
            Air air = new Air(1.21).WithLogarithmicWind(new Vector3d(4, 1, 0), 10, 0.03);
            var model = new FlightModel(Ball.Tennis, air, Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance,
                SpeedProportionalSpinDecay.TennisCrossLindsey);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            FlightState end = default;
            Action fly = () => end = Shots.Fly(model, RungeKutta4.Instance, start, 1e-4, 10_000);
            long allocated = Allocation.SteadyStateBytes(fly);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(end.IsFinite, Is.True);
        }

        [Test]
        public void BadProfile_IsRefusedNamingTheParameter()
        {
            Assert.That(() => new LogarithmicWindProfile(10, 0), Throws.InstanceOf<ArgumentException>().With.Message.Contains("roughnessLength"));
            Assert.That(() => new LogarithmicWindProfile(0.01, 0.03), Throws.InstanceOf<ArgumentException>().With.Message.Contains("referenceHeight"));
            Assert.That(() => new LogarithmicWindProfile(double.NaN, 0.03), Throws.InstanceOf<ArgumentException>().With.Message.Contains("referenceHeight"));
            Assert.That(() => Air.SeaLevel.WithLogarithmicWind(Breeze, 10, 0.03, new Vector3d(0, double.NaN, 0)),
                Throws.InstanceOf<ArgumentException>().With.Message.Contains("groundPoint"));
            Assert.That(() => Air.SeaLevel.WithLogarithmicWind(new Vector3d(double.NaN, 0, 0)), Throws.InstanceOf<ArgumentException>().With.Message.Contains("wind"));
        }
    }
}
