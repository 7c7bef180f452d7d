using System;
using System.Collections.Generic;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Api
{
    /// <summary>
    /// Every bad argument is refused with an ArgumentException that names the parameter and its allowed
    /// range, before anything changes.
    /// </summary>
    [TestFixture]
    public class BadInputTests
    {
        private static readonly FlightModel Model = Shots.StepanekTennis(Gravity.ZUp);
        private static readonly FlightState Good = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 0, 3), new Vector3d(0, 100, 0));

        public sealed class Case
        {
            public Case(string name, string parameter, string allowed, TestDelegate action)
            {
                Name = name;
                Parameter = parameter;
                Allowed = allowed;
                Action = action;
            }

            public string Name { get; }
            public string Parameter { get; }
            public string Allowed { get; }
            public TestDelegate Action { get; }
            public override string ToString() => Name;
        }

        public static IEnumerable<Case> Cases()
        {
            yield return new Case("mass zero", "mass", "> 0", () => new Ball(0, 0.033));
            yield return new Case("mass negative", "mass", "> 0", () => new Ball(-0.057, 0.033));
            yield return new Case("mass NaN", "mass", "finite", () => new Ball(double.NaN, 0.033));
            yield return new Case("mass infinite", "mass", "finite", () => new Ball(double.PositiveInfinity, 0.033));
            yield return new Case("radius zero", "radius", "> 0", () => new Ball(0.057, 0));
            yield return new Case("radius negative", "radius", "> 0", () => new Ball(0.057, -1));
            yield return new Case("radius NaN", "radius", "finite", () => new Ball(0.057, double.NaN));
            yield return new Case("inertia factor zero", "inertiaFactor", "(0, 1]", () => new Ball(0.057, 0.033, 0));
            yield return new Case("inertia factor above 1", "inertiaFactor", "(0, 1]", () => new Ball(0.057, 0.033, 1.5));
            yield return new Case("density negative", "density", ">= 0", () => new Air(-0.1));
            yield return new Case("density NaN", "density", "finite", () => new Air(double.NaN));
            yield return new Case("density infinite", "density", "finite", () => new Air(double.PositiveInfinity));
            yield return new Case("wind NaN", "wind", "finite", () => new Air(1.2, new Vector3d(double.NaN, 0, 0)));
            yield return new Case("viscosity zero", "dynamicViscosity", "> 0", () => new Air(1.2, default, 0));
            yield return new Case("drag coefficient negative", "dragCoefficient", ">= 0", () => new ConstantDrag(-0.1));
            yield return new Case("drag coefficient NaN", "dragCoefficient", "finite", () => new ConstantDrag(double.NaN));
            yield return new Case("lift coefficient infinite", "liftCoefficient", "finite", () => new ConstantLift(double.NegativeInfinity));
            yield return new Case("lift slope NaN", "slope", "finite", () => new LinearSpinLift(double.NaN));
            yield return new Case("spin decay tau zero", "timeConstant", "> 0", () => new ExponentialSpinDecay(0));
            yield return new Case("spin decay tau infinite", "timeConstant", "finite", () => new ExponentialSpinDecay(double.PositiveInfinity));
            yield return new Case("gravity NaN", "gravity", "finite", () => new FlightModel(Ball.Tennis, Air.SeaLevel, new Vector3d(0, 0, double.NaN)));
            yield return new Case("gravity infinite", "gravity", "finite", () => Model.WithGravity(new Vector3d(double.NegativeInfinity, 0, 0)));
            yield return new Case("ball null", "ball", "null", () => new FlightModel(null!, Air.SeaLevel, Gravity.ZUp));
            yield return new Case("air null", "air", "null", () => new FlightModel(Ball.Tennis, null!, Gravity.ZUp));
            foreach (IIntegrator integrator in Integrators.All)
            {
                string n = integrator.Name;
                yield return new Case($"{n}: step zero", "step", "> 0", () => integrator.Step(Model, Good, 0));
                yield return new Case($"{n}: step negative", "step", "> 0", () => integrator.Step(Model, Good, Model.Derivative(Good), -0.01));
                yield return new Case($"{n}: step NaN", "step", "finite", () => integrator.Step(Model, Good, double.NaN));
                yield return new Case($"{n}: step infinite", "step", "finite", () => integrator.Step(Model, Good, double.PositiveInfinity));
                yield return new Case($"{n}: position NaN", "state", "finite",
                    () => integrator.Step(Model, new FlightState(new Vector3d(double.NaN, 0, 0), Good.Velocity, Good.AngularVelocity), 0.01));
                yield return new Case($"{n}: velocity infinite", "state", "finite",
                    () => integrator.Step(Model, new FlightState(Good.Position, new Vector3d(0, double.PositiveInfinity, 0), Good.AngularVelocity), 0.01));
                yield return new Case($"{n}: spin NaN", "state", "finite",
                    () => integrator.Step(Model, new FlightState(Good.Position, Good.Velocity, new Vector3d(0, 0, double.NaN)), 0.01));
                yield return new Case($"{n}: time NaN", "state", "finite",
                    () => integrator.Step(Model, new FlightState(Good.Position, Good.Velocity, Good.AngularVelocity, double.NaN), 0.01));
                yield return new Case($"{n}: model null", "model", "null", () => integrator.Step(null!, Good, 0.01));
            }

            yield return new Case("state position NaN", "position", "finite", () => FlightState.Create(new Vector3d(double.NaN, 0, 0), default, default));
            yield return new Case("state time infinite", "time", "finite", () => FlightState.Create(default, default, default, double.PositiveInfinity));
            yield return new Case("spin toward parallel", "direction", "parallel", () => Spin.Toward(new Vector3d(1, 0, 0), new Vector3d(2, 0, 0), 10));
            yield return new Case("spin toward zero velocity", "velocity", "non-zero", () => Spin.Toward(Vector3d.Zero, Vector3d.UnitY, 10));
            yield return new Case("spin negative rate", "rate", ">= 0", () => Spin.Topspin(Vector3d.UnitX, Vector3d.UnitZ, -5));
            // Topspin and Backspin name their own parameter, up (they named Toward's "direction", which the caller never gave).
            yield return new Case("topspin on a vertical ball", "up", "parallel", () => Spin.Topspin(Vector3d.UnitZ, Vector3d.UnitZ, 5));
            yield return new Case("backspin on a vertical ball", "up", "parallel", () => Spin.Backspin(-Vector3d.UnitZ, Vector3d.UnitZ, 5));
            yield return new Case("topspin with a zero up", "up", "non-zero", () => Spin.Topspin(Vector3d.UnitX, Vector3d.Zero, 5));
            yield return new Case("backspin with a NaN up", "up", "finite", () => Spin.Backspin(Vector3d.UnitX, new Vector3d(0, 0, double.NaN), 5));
            // LaunchSpin.Backspin named "topspin" for a bad rate.
            yield return new Case("launch backspin NaN", "rate", "finite", () => LaunchSpin.Backspin(double.NaN));
            yield return new Case("integrator unknown", "name", "rk4", () => Integrators.FromName("rk5"));
            yield return new Case("gravity along zero up", "up", "non-zero", () => Gravity.Along(Vector3d.Zero));
        }

        [TestCaseSource(nameof(Cases))]
        public void IsRefused_WithTheParameterAndItsRangeNamed(Case c)
        {
            var error = Assert.Throws(Is.InstanceOf<ArgumentException>(), c.Action);
            var argumentError = (ArgumentException)error!;
            Assert.That(argumentError.ParamName, Is.EqualTo(c.Parameter));
            Assert.That(argumentError.Message, Does.Contain(c.Allowed));
        }

        [Test]
        public void ThereAreAtLeastTwentyCases()
        {
            Assert.That(new List<Case>(Cases()).Count, Is.GreaterThanOrEqualTo(20));
        }

        [Test]
        public void AFailedStep_LeavesTheCallersStateAsItWas()
        {
            FlightState state = Good;
            FlightState copy = state;
            Assert.Throws<ArgumentOutOfRangeException>(() => state = ((IIntegrator)RungeKutta4.Instance).Step(Model, state, double.NaN));
            Assert.That(state.Position, Is.EqualTo(copy.Position));
            Assert.That(state.Velocity, Is.EqualTo(copy.Velocity));
            Assert.That(state.AngularVelocity, Is.EqualTo(copy.AngularVelocity));
            Assert.That(state.Time, Is.EqualTo(copy.Time));
        }
    }
}
