using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Integration
{
    /// <summary>Integrators against problems with a closed-form solution.</summary>
    [TestFixture]
    public class ClosedFormTests
    {
        private static readonly Vector3d P0 = new Vector3d(1, -2, 1.5);
        private static readonly Vector3d V0 = new Vector3d(20, 3, 12);
        private static readonly Vector3d G = Gravity.ZUp;

        [Test]
        public void Rk4_InVacuum_MatchesTheParabola_To1e9MetresOver3Seconds()
        {
            FlightModel model = FlightModel.Vacuum(Ball.Tennis, G);
            var state = new FlightState(P0, V0, new Vector3d(0, 50, 0));
            const double step = 0.01;
            StateDerivative derivative = model.Derivative(state);
            for (int i = 1; i <= 300; i++)
            {
                state = ((IIntegrator)RungeKutta4.Instance).Step(model, state, derivative, step);
                derivative = model.Derivative(state);
                double t = i * step;
                Vector3d exact = P0 + V0 * t + G * (0.5 * t * t);
                // 1e-9 m: RK4 is exact on a quadratic; only rounding of ~300 sums of 10-m-sized terms remains.
                Assert.That(Vector3d.Distance(state.Position, exact), Is.LessThan(1e-9), $"at t={t}");
                Assert.That(Vector3d.Distance(state.Velocity, V0 + G * t), Is.LessThan(1e-9), $"at t={t}");
            }
        }

        [Test]
        public void ExplicitEuler_InVacuum_IsExactInVelocity_AndLagsByGhtOver2()
        {
            FlightModel model = FlightModel.Vacuum(Ball.Tennis, G);
            var state = new FlightState(P0, V0, Vector3d.Zero);
            const double step = 1.0 / 60;
            StateDerivative derivative = model.Derivative(state);
            for (int i = 1; i <= 180; i++)
            {
                state = ((IIntegrator)ExplicitEuler.Instance).Step(model, state, derivative, step);
                derivative = model.Derivative(state);
                double t = i * step;
                Vector3d exact = P0 + V0 * t + G * (0.5 * t * t);

                // Closed form of forward Euler on constant acceleration: x_n = x0 + v0 t + g t (t - h) / 2,
                // i.e. the exact parabola minus g h t / 2.
                Vector3d predictedError = G * (-0.5 * step * t);
                // 1e-10 m: rounding only; the error itself is up to 0.25 m here.
                Assert.That(Vector3d.Distance(state.Position - exact, predictedError), Is.LessThan(1e-10), $"at t={t}");
                Assert.That(Vector3d.Distance(state.Velocity, V0 + G * t), Is.LessThan(1e-11), $"at t={t}");
            }

            Assert.That((state.Position - (P0 + V0 * 3 + G * 4.5)).Length, Is.GreaterThan(0.2), "the Euler lag is real, not rounding");
        }

        [Test]
        public void Rk4_VerticalFallWithQuadraticDrag_MatchesTanhLaw_To1e9Relative()
        {
            // Falling from rest: v(t) = v_t tanh(g t / v_t) with terminal speed v_t = sqrt(g / (k C_D)), k = rho A / 2m.
            const double cd = 0.55;
            var model = new FlightModel(Ball.Tennis, new Air(1.21), G, new ConstantDrag(cd));
            double g = Gravity.Standard;
            double terminal = Math.Sqrt(g / (model.AerodynamicFactor * cd));
            var state = new FlightState(new Vector3d(0, 0, 100), Vector3d.Zero, Vector3d.Zero);
            const double step = 0.001;
            StateDerivative derivative = model.Derivative(state);
            for (int i = 1; i <= 5000; i++)
            {
                state = ((IIntegrator)RungeKutta4.Instance).Step(model, state, derivative, step);
                derivative = model.Derivative(state);
                if (i % 100 != 0)
                {
                    continue;
                }

                double t = i * step;
                double exact = terminal * Math.Tanh(g * t / terminal);
                // 1e-9 relative: RK4's local error at 1 ms is ~h^5 |v'''''| ~ 1e-15; this bounds its sum plus rounding.
                Assert.That(Math.Abs(-state.Velocity.Z - exact) / exact, Is.LessThan(1e-9), $"at t={t}");
                Assert.That(state.Velocity.X, Is.EqualTo(0));
            }
        }
    }
}
