using System;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Integration
{
    /// <summary>
    /// The spec of the integration layer: each method's textbook combination, written out once, on a given right-hand side
    /// (for the spec itself, the physics layer's general formula, FlightModel.GeneralDerivative). The library's own steps run
    /// through the flight kernel (Integration/Kernels); the conformance test (tests/MagnusBall.Tests/Integration/ConformanceTests.cs)
    /// holds every one of them to these. Euler's y + h k1 and semi-implicit Euler's v + h a, p + h v' are written as such in
    /// ExplicitEuler.cs, which is their spec. Not for flights: these allocate and are slow on purpose, to stay readable.
    /// </summary>
    internal static class Textbook
    {
        /// <summary>Heun: k2 = f(y + h k1), then y + h/2 (k1 + k2).</summary>
        internal static FlightState Heun(Func<FlightState, StateDerivative> f, in FlightState y, in StateDerivative k1, double h)
        {
            StateDerivative k2 = f(y.Advance(k1, h));
            double half = 0.5 * h;
            return new FlightState(
                y.Position + (k1.Velocity + k2.Velocity) * half,
                y.Velocity + (k1.Acceleration + k2.Acceleration) * half,
                y.AngularVelocity + (k1.AngularAcceleration + k2.AngularAcceleration) * half,
                y.Time + h);
        }

        /// <summary>Classic RK4: k2 = f(y + h/2 k1), k3 = f(y + h/2 k2), k4 = f(y + h k3), then y + h/6 (k1 + 2 (k2 + k3) + k4).</summary>
        internal static FlightState Rk4(Func<FlightState, StateDerivative> f, in FlightState y, in StateDerivative k1, double h)
        {
            double half = 0.5 * h;
            StateDerivative k2 = f(y.Advance(k1, half));
            StateDerivative k3 = f(y.Advance(k2, half));
            StateDerivative k4 = f(y.Advance(k3, h));
            double sixth = h / 6.0;
            return new FlightState(
                y.Position + (k1.Velocity + 2.0 * (k2.Velocity + k3.Velocity) + k4.Velocity) * sixth,
                y.Velocity + (k1.Acceleration + 2.0 * (k2.Acceleration + k3.Acceleration) + k4.Acceleration) * sixth,
                y.AngularVelocity + (k1.AngularAcceleration + 2.0 * (k2.AngularAcceleration + k3.AngularAcceleration) + k4.AngularAcceleration) * sixth,
                y.Time + h);
        }

        /// <summary>
        /// Dormand &amp; Prince's (1980) tableau: the stages k2..k6 from its rows, the fifth-order end y + h (b1 k1 + b3 k3 +
        /// b4 k4 + b5 k5 + b6 k6) and k7 = f(end), each sum left to right as DormandPrince54 forms it. Every stage's state
        /// is formed in full (positions and spins too), so the stages are the tableau's whatever a fast form leaves out.
        /// k: k2..k7.
        /// </summary>
        internal static FlightState Dp54(Func<FlightState, StateDerivative> f, in FlightState y, in StateDerivative k1, double h, out StateDerivative[] k)
        {
            StateDerivative k2 = f(y.Advance(k1, (1.0 / 5) * h));
            StateDerivative k3 = f(Sum(y, h, new[] { k1, k2 }, new[] { 3.0 / 40, 9.0 / 40 }));
            StateDerivative k4 = f(Sum(y, h, new[] { k1, k2, k3 }, new[] { 44.0 / 45, -56.0 / 15, 32.0 / 9 }));
            StateDerivative k5 = f(Sum(y, h, new[] { k1, k2, k3, k4 }, new[] { 19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729 }));
            StateDerivative k6 = f(
                Sum(y, h, new[] { k1, k2, k3, k4, k5 }, new[] { 9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656 }));
            FlightState end = Sum(y, h, new[] { k1, k3, k4, k5, k6 }, new[] { 35.0 / 384, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84 });
            end = new FlightState(end.Position, end.Velocity, end.AngularVelocity, y.Time + h);
            StateDerivative k7 = f(end);
            k = new[] { k2, k3, k4, k5, k6, k7 };
            return end;
        }

        private static FlightState Sum(in FlightState y, double h, StateDerivative[] k, double[] a)
        {
            Vector3d p = y.Position, v = y.Velocity, w = y.AngularVelocity;
            for (int i = 0; i < k.Length; i++)
            {
                double c = h * a[i];
                p += k[i].Velocity * c;
                v += k[i].Acceleration * c;
                w += k[i].AngularAcceleration * c;
            }

            return new FlightState(p, v, w, y.Time);
        }
    }
}
