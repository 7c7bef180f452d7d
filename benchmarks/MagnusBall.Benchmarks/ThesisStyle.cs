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

    /// <summary>
    /// The full tennis model (<see cref="Scenarios.FullTennis"/>: Stepanek's drag and lift, exponential spin decay) written
    /// in the thesis's style, as a developer who follows the thesis and then adds the tennis laws would write it: the spin
    /// joins the state (a7..a9 = w), Stepanek's laws straight from their formulas with <c>Math.Pow</c>, fresh arrays for
    /// every stage. The same forces as the library's model (the lift in its transverse-spin form, (k C_L s^2 / |w|)
    /// (w x v_hat)); "peers-check" compares the two flights. The naive code a game on the full model replaces: the unit
    /// the full-model workloads are also measured against (docs/performance.md).
    /// </summary>
    internal sealed class ThesisStyleTennisBall
    {
        private readonly double _k; // rho A / 2m
        private readonly double _r;
        private readonly double _tau;
        private readonly double _g;
        private double[] _a;

        public ThesisStyleTennisBall(Ball ball, double density, double spinDecayTime, double g, double[] start)
        {
            _k = density * Math.PI * ball.Radius * ball.Radius / (2 * ball.Mass);
            _r = ball.Radius;
            _tau = spinDecayTime;
            _g = g;
            _a = (double[])start.Clone();
        }

        public double[] State => _a;

        /// <summary>The code with <see cref="Scenarios.FullTennis"/>'s ball, air, spin decay and gravity, from <paramref name="start"/>.</summary>
        public static ThesisStyleTennisBall FullTennis(double[] start) =>
            new ThesisStyleTennisBall(Ball.Tennis, 1.21, Scenarios.FullTennisSpinDecayTime, Gravity.Standard, start);

        /// <summary>A flight state as this code's a1..a9 (the time is not part of it).</summary>
        public static double[] StateOf(in FlightState state)
        {
            Vector3d p = state.Position, v = state.Velocity, w = state.AngularVelocity;
            return new[] { p.X, v.X, p.Y, v.Y, p.Z, v.Z, w.X, w.Y, w.Z };
        }

        public void Reset(double[] start) => _a = (double[])start.Clone();

        /// <summary>The derivative of a1..a9 = x, x', y, y', z, z', wx, wy, wz.</summary>
        public double[] DifferentialEquations(double[] a)
        {
            double vx = a[1], vy = a[3], vz = a[5], wx = a[6], wy = a[7], wz = a[8];
            double speed = Math.Sqrt(vx * vx + vy * vy + vz * vz);
            double omega = Math.Sqrt(wx * wx + wy * wy + wz * wz);
            double cx = wy * vz - wz * vy, cy = wz * vx - wx * vz, cz = wx * vy - wy * vx;
            double cross = Math.Sqrt(cx * cx + cy * cy + cz * cz);

            // Stepanek's drag: C_D = 0.508 + (22.053 + 4.196 (1/S)^2.5)^-0.4, S = r |w| / s
            double cd = 0.508;
            if (omega > 0)
            {
                cd += Math.Pow(22.053 + 4.196 * Math.Pow(speed / (_r * omega), 2.5), -0.4);
            }

            // Stepanek's lift: C_L = S_perp / (2.022 S_perp + 0.981), S_perp = r |w x v| / s^2; F / m = k C_L s^2 (w x v_hat) / |w|
            double magnus = 0;
            if (cross > 0)
            {
                double sPerp = _r * cross / (speed * speed);
                double cl = sPerp / (2.022 * sPerp + 0.981);
                magnus = _k * cl * speed / omega;
            }

            return new[]
            {
                vx, -_k * cd * speed * vx + magnus * cx,
                vy, -_k * cd * speed * vy + magnus * cy,
                vz, -_k * cd * speed * vz + magnus * cz - _g,
                -wx / _tau, -wy / _tau, -wz / _tau,
            };
        }

        /// <summary>
        /// 480 steps of 1/240 s from <paramref name="start"/> by this code and by the library's RK4 on
        /// <see cref="Scenarios.FullTennis"/>: the largest difference of position, velocity and spin, each relative to its own
        /// size (at least 1), and the library's end state ("peers-check").
        /// </summary>
        public static double DifferenceFromLibrary(in FlightState start, out FlightState end)
        {
            FlightModel model = Scenarios.FullTennis();
            end = start;
            StateDerivative derivative = model.Derivative(end);
            MagnusBall.Integration.RungeKutta4.Instance.Advance(model, ref end, ref derivative, Workloads.Step, Workloads.ShotSteps);
            ThesisStyleTennisBall naive = FullTennis(StateOf(start));
            for (int i = 0; i < Workloads.ShotSteps; i++)
            {
                naive.Update(Workloads.Step);
            }

            double[] a = naive.State;
            return Math.Max(
                Math.Max(Relative(end.Position, new Vector3d(a[0], a[2], a[4])), Relative(end.Velocity, new Vector3d(a[1], a[3], a[5]))),
                Relative(end.AngularVelocity, new Vector3d(a[6], a[7], a[8])));

            static double Relative(in Vector3d x, in Vector3d y) => (x - y).Length / Math.Max(1, y.Length);
        }

        /// <summary>One RK4 step, fresh arrays per stage, as <see cref="ThesisStyleBall.SolveRungaKutta"/>.</summary>
        public void SolveRungaKutta(double h)
        {
            // ThesisStyleBall's RK4 written again for nine states, not shared: sharing it would change the code U times.
            double[] k1 = DifferentialEquations(_a);
            double[] y2 = new double[9];
            for (int i = 0; i < 9; i++)
            {
                y2[i] = _a[i] + h / 2 * k1[i];
            }

            double[] k2 = DifferentialEquations(y2);
            double[] y3 = new double[9];
            for (int i = 0; i < 9; i++)
            {
                y3[i] = _a[i] + h / 2 * k2[i];
            }

            double[] k3 = DifferentialEquations(y3);
            double[] y4 = new double[9];
            for (int i = 0; i < 9; i++)
            {
                y4[i] = _a[i] + h * k3[i];
            }

            double[] k4 = DifferentialEquations(y4);
            double[] next = new double[9];
            for (int i = 0; i < 9; i++)
            {
                next[i] = _a[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
            }

            _a = next;
        }

        /// <summary>The frame loop: one RK4 step per Update with the frame's delta time.</summary>
        public void Update(double deltaTime) => SolveRungaKutta(deltaTime);
    }
}
