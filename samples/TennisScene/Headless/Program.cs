using System;
using System.Globalization;
using MagnusBall;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;

namespace MagnusBall.Samples.TennisScene.Headless
{
    /// <summary>
    /// A minimal headless run of one tennis shot: a 30 m/s topspin drive from 1 m, stepped with RK4 at
    /// 1/240 s under Stepanek's coefficients, printing where it lands.
    /// </summary>
    public static class Program
    {
        /// <summary>Entry point.</summary>
        public static int Main()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            double elevation = 8 * Math.PI / 180;
            var velocity = new Vector3d(30 * Math.Cos(elevation), 0, 30 * Math.Sin(elevation));
            var state = new FlightState(new Vector3d(0, 0, 1), velocity, Spin.Topspin(velocity, Vector3d.UnitZ, Spin.FromRevolutionsPerSecond(20)));
            IIntegrator integrator = RungeKutta4.Instance;
            const double step = 1.0 / 240;
            StateDerivative derivative = model.Derivative(state);
            while (true)
            {
                FlightState next = integrator.Step(model, state, derivative, step);
                if (next.Position.Z < 0)
                {
                    double f = state.Position.Z / (state.Position.Z - next.Position.Z);
                    Vector3d landing = Vector3d.Lerp(state.Position, next.Position, f);
                    double time = state.Time + f * step;
                    Console.WriteLine(string.Format(
                        CultureInfo.InvariantCulture,
                        "topspin drive 30 m/s, 8 deg, 20 rev/s: lands at x = {0:F3} m, y = {1:F3} m after {2:F3} s",
                        landing.X, landing.Y, time));
                    return 0;
                }

                state = next;
                derivative = model.Derivative(state);
            }
        }
    }
}
