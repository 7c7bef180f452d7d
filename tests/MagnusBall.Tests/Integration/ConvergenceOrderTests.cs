using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Integration
{
    /// <summary>Measured convergence order of every integrator on a spinning tennis shot.</summary>
    [TestFixture]
    public class ConvergenceOrderTests
    {
        private const double EndTime = 1.0;

        private static FlightModel Model() =>
            new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));

        private static FlightState Start()
        {
            Vector3d velocity = new Vector3d(30 * Math.Cos(0.15), 0, 30 * Math.Sin(0.15));
            return new FlightState(new Vector3d(0, 0, 1), velocity, Spin.Topspin(velocity, Vector3d.UnitZ, Spin.FromRevolutionsPerSecond(30)));
        }

        private static double EndError(IIntegrator integrator, int steps, in FlightState reference)
        {
            FlightState end = Shots.Fly(Model(), integrator, Start(), EndTime / steps, steps);
            return Math.Sqrt((end.Position - reference.Position).LengthSquared + (end.Velocity - reference.Velocity).LengthSquared);
        }

        [TestCase("euler", 1, new[] { 100, 200, 400, 800 })]
        [TestCase("semi-implicit-euler", 1, new[] { 100, 200, 400, 800 })]
        [TestCase("heun", 2, new[] { 50, 100, 200, 400 })]
        [TestCase("rk4", 4, new[] { 10, 20, 40, 80 })]
        public void LogLogSlopeOfEndStateError_IsTheMethodsOrder(string name, int order, int[] stepCounts)
        {
            IIntegrator integrator = Integrators.FromName(name);
            Assert.That(integrator.Order, Is.EqualTo(order));

            // The reference: RK4 at 1e-5 s (its own error ~1e-5^4 is far below every error measured here).
            FlightState reference = Shots.Fly(Model(), RungeKutta4.Instance, Start(), 1e-5, 100_000);

            double[] logStep = new double[stepCounts.Length];
            double[] logError = new double[stepCounts.Length];
            for (int i = 0; i < stepCounts.Length; i++)
            {
                logStep[i] = Math.Log(EndTime / stepCounts[i]);
                logError[i] = Math.Log(EndError(integrator, stepCounts[i], reference));
            }

            double slope = LeastSquaresSlope(logStep, logError);
            TestContext.Out.WriteLine($"{name}: measured order {slope:F3}");
            // 0.15: the bound; the asymptotic regime at these steps leaves slopes within a few hundredths.
            Assert.That(slope, Is.EqualTo(order).Within(0.15));
        }

        private static double LeastSquaresSlope(double[] x, double[] y)
        {
            double mx = 0, my = 0;
            for (int i = 0; i < x.Length; i++)
            {
                mx += x[i] / x.Length;
                my += y[i] / y.Length;
            }

            double sxy = 0, sxx = 0;
            for (int i = 0; i < x.Length; i++)
            {
                sxy += (x[i] - mx) * (y[i] - my);
                sxx += (x[i] - mx) * (x[i] - mx);
            }

            return sxy / sxx;
        }
    }
}
