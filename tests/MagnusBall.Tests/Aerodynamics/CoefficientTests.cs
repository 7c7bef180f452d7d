using System;
using MagnusBall.Aerodynamics;
using NUnit.Framework;

namespace MagnusBall.Tests.Aerodynamics
{
    [TestFixture]
    public class CoefficientTests
    {
        private static AeroConditions At(double speed, double spin, double transverseSpin, double radius = 0.033) =>
            new AeroConditions(speed, spin, transverseSpin, radius, 1.21, Air.SeaLevelDynamicViscosity);

        [Test]
        public void Stepanek_LimitsAndAKnownPoint()
        {
            Assert.That(StepanekDrag.Evaluate(0), Is.EqualTo(0.508));
            Assert.That(StepanekLift.Evaluate(0), Is.EqualTo(0));
            // S -> infinity: C_D -> 0.508 + 22.053^-0.4, C_L -> 1/2.022.
            Assert.That(StepanekDrag.Evaluate(1e9), Is.EqualTo(0.508 + Math.Pow(22.053, -0.4)).Within(1e-12));
            Assert.That(StepanekLift.Evaluate(1e12), Is.EqualTo(1 / 2.022).Within(1e-9));
            // S = 0.2: 1/S = 5, C_D = 0.508 + (22.053 + 4.196 * 5^2.5)^-0.4, C_L = 1/(2.022 + 4.905).
            Assert.That(StepanekDrag.Evaluate(0.2), Is.EqualTo(0.508 + Math.Pow(22.053 + 4.196 * Math.Pow(5, 2.5), -0.4)).Within(1e-15));
            Assert.That(StepanekLift.Evaluate(0.2), Is.EqualTo(1 / (2.022 + 4.905)).Within(1e-15));
            Assert.That(StepanekDrag.Evaluate(1e-300), Is.EqualTo(0.508), "(1/S)^2.5 overflows to the right limit");
        }

        [Test]
        public void DragReadsTheWholeSpin_LiftReadsTheTransverseSpin()
        {
            // Spin half along the flight: S counts all of it, S_perp only the transverse half.
            AeroConditions c = At(30, 200, 100);
            Assert.That(c.SpinParameter, Is.EqualTo(0.033 * 200 / 30).Within(1e-15));
            Assert.That(c.TransverseSpinParameter, Is.EqualTo(0.033 * 100 / 30).Within(1e-15));
            Assert.That(new LinearSpinLift(0.6).LiftCoefficient(c), Is.EqualTo(0.6 * 0.033 * 100 / 30).Within(1e-15));
            Assert.That(StepanekLift.Instance.LiftCoefficient(c), Is.EqualTo(StepanekLift.Evaluate(0.11)).Within(1e-15));
            Assert.That(StepanekDrag.Instance.DragCoefficient(c), Is.EqualTo(StepanekDrag.Evaluate(0.22)).Within(1e-15));
        }

        [Test]
        public void ReynoldsNumber_OfATennisBallAt30MetresPerSecond()
        {
            // rho s d / mu = 1.21 * 30 * 0.066 / 1.81e-5 = 132,000.
            Assert.That(At(30, 0, 0).ReynoldsNumber, Is.EqualTo(1.21 * 30 * 0.066 / 1.81e-5).Within(1e-6));
        }

        [Test]
        public void ExponentialSpinDecay_HalvesSpinInTauLn2()
        {
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.ZUp, spinDecay: new ExponentialSpinDecay(2));
            var state = new FlightState(Vector3d.Zero, Vector3d.UnitX, new Vector3d(0, 100, 0));
            int steps = 10_000;
            FlightState end = Shots.Fly(model, MagnusBall.Integration.RungeKutta4.Instance, state, 2 * Math.Log(2) / steps, steps);
            // 1e-9 rad/s: RK4 on a linear ODE at h = 1.4e-4 s has relative error ~h^4/120/tau^4 ~ 1e-19.
            Assert.That(end.AngularVelocity.Y, Is.EqualTo(50).Within(1e-9));
        }
    }
}
