using System;
using MathNet.Numerics.LinearAlgebra;
using MathNet.Numerics.OdeSolvers;

namespace MagnusBall.Benchmarks
{
    /// <summary>MathNet.Numerics 5.0.0's <c>RungeKutta.FourthOrder</c> on the same ODE, as its API asks for it.</summary>
    internal sealed class MathNetPeer
    {
        private readonly double _kd, _km, _wx, _wy, _wz, _g;
        private readonly Func<double, Vector<double>, Vector<double>> _f;

        public MathNetPeer(double mass, double radius, double density, double cd, double cm, double g, double wx, double wy, double wz)
        {
            double area = Math.PI * radius * radius;
            _kd = density * area * cd / (2 * mass);
            _km = density * area * cm / (2 * mass);
            _g = g;
            _wx = wx;
            _wy = wy;
            _wz = wz;
            _f = Derivative;
        }

        private Vector<double> Derivative(double t, Vector<double> a)
        {
            double vx = a[1], vy = a[3], vz = a[5];
            double speed = Math.Sqrt(vx * vx + vy * vy + vz * vz);
            double cx = _wy * vz - _wz * vy, cy = _wz * vx - _wx * vz, cz = _wx * vy - _wy * vx;
            double cross = Math.Sqrt(cx * cx + cy * cy + cz * cz);
            double magnus = cross > 0 ? _km * speed * speed / cross : 0;
            return Vector<double>.Build.Dense(new[]
            {
                vx, -_kd * speed * vx + magnus * cx,
                vy, -_kd * speed * vy + magnus * cy,
                vz, -_kd * speed * vz + magnus * cz - _g,
            });
        }

        /// <summary>Integrates <paramref name="steps"/> RK4 steps over [0, duration]; returns the last state.</summary>
        public Vector<double> Solve(Vector<double> start, double duration, int steps)
        {
            Vector<double>[] trajectory = RungeKutta.FourthOrder(start, 0, duration, steps + 1, _f);
            return trajectory[trajectory.Length - 1];
        }
    }
}
