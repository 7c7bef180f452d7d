using System;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// The thesis's own algorithm as its section 3.1.3 describes it (Agrawal 2023): a <c>DifferentialEquations</c> function
    /// over a1..a6 = x, x', y, y', z, z' that returns a fresh array, an RK4 that builds fresh arrays for every stage, and a
    /// per-frame update loop. Constant K_D and K_M, the thesis's Magnus direction (w x v)/|w x v|, z up. Written here
    /// from the description, as a developer following the thesis would write it.
    /// </summary>
    internal sealed class ThesisStyleBall
    {
        private readonly double _kd; // rho A C_D / 2m
        private readonly double _km; // rho A C_M / 2m
        private readonly double _wx, _wy, _wz;
        private readonly double _g;
        private double[] _a;

        public ThesisStyleBall(double mass, double radius, double density, double cd, double cm, double g, double[] start, double wx, double wy, double wz)
        {
            double area = Math.PI * radius * radius;
            _kd = density * area * cd / (2 * mass);
            _km = density * area * cm / (2 * mass);
            _g = g;
            _a = (double[])start.Clone();
            _wx = wx;
            _wy = wy;
            _wz = wz;
        }

        public double[] State => _a;

        public void Reset(double[] start) => _a = (double[])start.Clone();

        /// <summary>Eq. (12)-(15): the derivative of a1..a6.</summary>
        public double[] DifferentialEquations(double[] a)
        {
            double vx = a[1], vy = a[3], vz = a[5];
            double speed = Math.Sqrt(vx * vx + vy * vy + vz * vz);
            double cx = _wy * vz - _wz * vy, cy = _wz * vx - _wx * vz, cz = _wx * vy - _wy * vx;
            double cross = Math.Sqrt(cx * cx + cy * cy + cz * cz);
            double magnus = cross > 0 ? _km * speed * speed / cross : 0;
            return new[]
            {
                vx, -_kd * speed * vx + magnus * cx,
                vy, -_kd * speed * vy + magnus * cy,
                vz, -_kd * speed * vz + magnus * cz - _g,
            };
        }

        /// <summary>One RK4 step, fresh arrays per stage, as the thesis's <c>SolveRungaKutta</c>.</summary>
        public void SolveRungaKutta(double h)
        {
            double[] k1 = DifferentialEquations(_a);
            double[] y2 = new double[6];
            for (int i = 0; i < 6; i++)
            {
                y2[i] = _a[i] + h / 2 * k1[i];
            }

            double[] k2 = DifferentialEquations(y2);
            double[] y3 = new double[6];
            for (int i = 0; i < 6; i++)
            {
                y3[i] = _a[i] + h / 2 * k2[i];
            }

            double[] k3 = DifferentialEquations(y3);
            double[] y4 = new double[6];
            for (int i = 0; i < 6; i++)
            {
                y4[i] = _a[i] + h * k3[i];
            }

            double[] k4 = DifferentialEquations(y4);
            double[] next = new double[6];
            for (int i = 0; i < 6; i++)
            {
                next[i] = _a[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
            }

            _a = next;
        }

        /// <summary>The frame loop: one RK4 step per Update with the frame's delta time.</summary>
        public void Update(double deltaTime) => SolveRungaKutta(deltaTime);
    }
}
