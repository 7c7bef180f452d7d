// Table-tennis drag and lift after Conti et al. (2026, arXiv:2606.28805): coefficients of a 40 mm ball fitted to recorded
// flights, as transcribed in two public repositories (data/coefficients/README.md). Internal: the table-tennis preset
// exposes them through IDragModel and ILiftModel.
namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Table-tennis drag after Conti et al. (2026): C_D of a 40 mm ball tabulated against the air-relative speed and the
    /// spin parameter S = r|w|/s, fitted to recorded flights of a table-tennis ball.
    /// </summary>
    /// <remarks>
    /// <para>Source: C. Conti, B. Yang, A. Sigrist, L. Miele, Y. Saraiji, P. Dürr and N. Takahashi (2026), "Physics
    /// Models for Sim-to-Real Transfer in Professional-Level Robot Table Tennis", arXiv:2606.28805 (Sony AI). Its abstract
    /// says drag and Magnus coefficients are modelled as functions of Reynolds number and spin ratio over the speeds and
    /// spins of professional play, fitted to recorded flights (not a wind tunnel). The numbers are <b>second-hand</b>:
    /// the paper's text could not be read here; they are its table as transcribed in two public repositories, which agree
    /// on every C_D (data/coefficients/conti-2026-table-tennis-drag.csv and README.md).</para>
    /// <para>Four rows, at 2.5, 7.5, 12.5 and 17.5 m/s (Re about 6.7e3-4.7e4), six points each in S from 0 to 2: without
    /// spin C_D is 0.55, 0.49, 0.47, 0.47 (a smooth sphere below its drag crisis, as wind-tunnel spheres are at these
    /// Reynolds numbers); it rises to 0.51-0.55 near S 0.5-0.75 and dips to 0.37-0.48 near S 0.84-1.1, the drag side of the
    /// "lift crisis" Miyazaki et al. (2017, Eur. J. Phys. 38:024001) measured on a spinning table-tennis ball.</para>
    /// <para>Evaluation: linear in S inside each row (held beyond S 2), then linear in speed between the rows (held below
    /// 2.5 and above 17.5 m/s). Continuous everywhere; between 0.37 and 0.55 for every input (NaN reads as the table's
    /// first entry). Range of validity: 2.5-17.5 m/s and S 0-2 for a 40 mm ball.</para>
    /// </remarks>
    internal sealed class ContiTableTennisDrag : IDragModel
    {
        /// <summary>The largest C_D of the table: the bound the law catalogue states.</summary>
        internal const double Largest = 0.55;

        private static readonly double[] Speeds = { 2.5, 7.5, 12.5, 17.5 };

        private static readonly double[][] RowSpin =
        {
            new[] { 0.0, 0.3, 0.7, 0.95, 1.5, 2.0 },
            new[] { 0.0, 0.4, 0.75, 1.1, 1.3, 2.0 },
            new[] { 0.0, 0.4, 0.62, 0.95, 1.3, 2.0 },
            new[] { 0.0, 0.4, 0.5, 0.84, 1.2, 2.0 },
        };

        private static readonly double[][] RowDrag =
        {
            new[] { 0.55, 0.55, 0.55, 0.55, 0.55, 0.55 },
            new[] { 0.49, 0.49, 0.55, 0.48, 0.53, 0.53 },
            new[] { 0.47, 0.47, 0.53, 0.41, 0.48, 0.48 },
            new[] { 0.47, 0.47, 0.51, 0.37, 0.45, 0.45 },
        };

        /// <summary>The shared instance (the law has no parameters).</summary>
        internal static ContiTableTennisDrag Instance { get; } = new ContiTableTennisDrag();

        private ContiTableTennisDrag()
        {
        }

        /// <inheritdoc />
        public double DragCoefficient(in AeroConditions conditions) => Evaluate(conditions.Speed, conditions.SpinParameter);

        /// <summary>C_D at air-relative speed <paramref name="speed"/> (m/s) and spin parameter <paramref name="spinParameter"/>.</summary>
        internal static double Evaluate(double speed, double spinParameter)
        {
            if (!(speed > Speeds[0]))
            {
                return Row(0, spinParameter);
            }

            for (int i = 1; i < Speeds.Length; i++)
            {
                if (speed <= Speeds[i])
                {
                    double t = (speed - Speeds[i - 1]) / (Speeds[i] - Speeds[i - 1]);
                    double low = Row(i - 1, spinParameter);
                    return low + t * (Row(i, spinParameter) - low);
                }
            }

            return Row(Speeds.Length - 1, spinParameter);
        }

        private static double Row(int row, double spinParameter)
        {
            double[] s = RowSpin[row];
            double[] c = RowDrag[row];
            if (!(spinParameter > 0))
            {
                return c[0];
            }

            for (int i = 1; i < s.Length; i++)
            {
                if (spinParameter <= s[i])
                {
                    double t = (spinParameter - s[i - 1]) / (s[i] - s[i - 1]);
                    return c[i - 1] + t * (c[i] - c[i - 1]);
                }
            }

            return c[c.Length - 1];
        }

        /// <inheritdoc />
        public override string ToString() => "ContiTableTennisDrag";
    }

    /// <summary>
    /// Table-tennis lift after Conti et al. (2026): their volume-based Magnus coefficient C_M of a 40 mm ball, fitted
    /// against the spin rate at six speeds with a valley (the "lift crisis"), written as the library's C_L = (8/3) C_M S.
    /// </summary>
    /// <remarks>
    /// <para>Source: as <see cref="ContiTableTennisDrag"/> (arXiv:2606.28805; fitted to recorded flights; <b>second-hand</b>,
    /// the two public transcriptions agree on all 36 numbers: data/coefficients/conti-2026-table-tennis-magnus.csv).</para>
    /// <para>The source writes F = C_M rho V (w x v), V = 4/3 pi r^3, and fits C_M at 2, 3.5, 7.5, 10.5, 13.5 and 17 m/s as
    /// a line in the spin rate |w| (rad/s) up to a breakpoint (150-650 rad/s) and a parabola above it. The library's force
    /// is 1/2 rho A C_L s^2 (w x v_hat)/|w|, so the same force is C_L = (8/3) C_M S with S = r|w|/s. C_M falls with spin,
    /// so C_L rises to about 0.25-0.30 near S 0.5, sags, and rises again: the valley Miyazaki et al. (2017, Eur. J. Phys.
    /// 38:024001) measured in flight on a Nittaku 3-star ball and called the lift crisis.</para>
    /// <para>Evaluation: each row's C_M at |w|, held at 0 where its parabola goes negative: at 2 m/s above 458 rad/s, at
    /// 3.5 m/s above 681, at 7.5 m/s above 1114, at 10.5 and 13.5 m/s above 1309-1335 and at 17 m/s above 2123 rad/s (the
    /// fit's own zeros); the two branches of a row differ by up to 0.022 in C_M at its breakpoint (an artefact of the
    /// piecewise fit), so they are blended linearly over the 40 rad/s around it, which keeps the force continuous; then
    /// linear in speed between the rows, held below 2 and above 17 m/s. S is held at 10 so that C_L stays below
    /// <see cref="Largest"/> as the speed goes to 0 (a bound, not a measurement); no NaN for any input (0 without spin, for
    /// NaN, and for infinite S). Range of validity: 2-17 m/s, a 40 mm ball, and at each speed the spins below its row's zero
    /// (a slow ball with heavy spin, 2 m/s above about 450 rad/s, gets no lift: the fit's limit, not the ball's). No
    /// negative C_L: this law has no reverse Magnus effect.</para>
    /// </remarks>
    internal sealed class ContiTableTennisLift : ILiftModel
    {
        /// <summary>S above which C_L is held.</summary>
        internal const double HeldSpinParameter = 10.0;

        /// <summary>A bound on C_L: (8/3) x the largest C_M (0.383) x S held at 10 = 10.21.</summary>
        internal const double Largest = 10.3;

        /// <summary>Half the window, rad/s, over which a row's two branches are blended at its breakpoint.</summary>
        internal const double BlendHalfWidth = 20.0;

        private static readonly double[] Speeds = { 2.0, 3.5, 7.5, 10.5, 13.5, 17.0 };

        // slope (s), intercept, breakpoint (rad/s)
        private static readonly double[][] Linear =
        {
            new[] { 0.0, 0.08, 150.0 },
            new[] { -1.1e-3, 0.31, 200.0 },
            new[] { -8.0e-4, 0.37, 350.0 },
            new[] { -6.58e-4, 0.375, 440.0 },
            new[] { -5.6e-4, 0.383, 550.0 },
            new[] { -4.48e-4, 0.371, 650.0 },
        };

        // a (s^2), b (s), c
        private static readonly double[][] Quadratic =
        {
            new[] { -1.852e-7, -1.296e-4, 0.0983 },
            new[] { -1.667e-7, -3.333e-5, 0.1 },
            new[] { -2.0e-7, 1.7e-4, 0.0587 },
            new[] { -2.604e-7, 3.646e-4, -0.0225 },
            new[] { -3.571e-7, 5.357e-4, -0.0893 },
            new[] { -1.0e-7, 2.3e-4, -0.0375 },
        };

        /// <summary>The shared instance (the law has no parameters).</summary>
        internal static ContiTableTennisLift Instance { get; } = new ContiTableTennisLift();

        private ContiTableTennisLift()
        {
        }

        /// <inheritdoc />
        public double LiftCoefficient(in AeroConditions conditions) =>
            Evaluate(conditions.Speed, conditions.SpinRate, conditions.SpinParameter);

        /// <summary>C_L = (8/3) C_M(s, |w|) min(S, 10); 0 without spin, for NaN and for infinite S.</summary>
        internal static double Evaluate(double speed, double spinRate, double spinParameter)
        {
            if (!(spinParameter > 0) || double.IsInfinity(spinParameter))
            {
                return 0.0;
            }

            double magnus = MagnusCoefficient(speed, spinRate);
            double s = spinParameter < HeldSpinParameter ? spinParameter : HeldSpinParameter;
            return magnus > 0 ? 8.0 / 3.0 * magnus * s : 0.0;
        }

        /// <summary>The source's C_M at <paramref name="speed"/> (m/s) and <paramref name="spinRate"/> (rad/s).</summary>
        internal static double MagnusCoefficient(double speed, double spinRate)
        {
            if (!(speed > Speeds[0]))
            {
                return Row(0, spinRate);
            }

            for (int i = 1; i < Speeds.Length; i++)
            {
                if (speed <= Speeds[i])
                {
                    double t = (speed - Speeds[i - 1]) / (Speeds[i] - Speeds[i - 1]);
                    double low = Row(i - 1, spinRate);
                    return low + t * (Row(i, spinRate) - low);
                }
            }

            return Row(Speeds.Length - 1, spinRate);
        }

        /// <summary>Row <paramref name="row"/>'s fit as printed (no blend), held at 0 from below: the tests' reference.</summary>
        internal static double RowAsFitted(int row, double spinRate) =>
            Positive(spinRate <= Linear[row][2] ? LinearBranch(row, spinRate) : QuadraticBranch(row, spinRate));

        /// <summary>The rows' speeds, m/s.</summary>
        internal static double RowSpeed(int row) => Speeds[row];

        /// <summary>The rows' breakpoints, rad/s.</summary>
        internal static double Breakpoint(int row) => Linear[row][2];

        private static double Row(int row, double spinRate)
        {
            double breakpoint = Linear[row][2];
            if (!(spinRate > breakpoint - BlendHalfWidth))
            {
                return Positive(LinearBranch(row, spinRate));
            }

            if (spinRate >= breakpoint + BlendHalfWidth)
            {
                return Positive(QuadraticBranch(row, spinRate));
            }

            double t = (spinRate - (breakpoint - BlendHalfWidth)) / (2 * BlendHalfWidth);
            double low = LinearBranch(row, spinRate);
            return Positive(low + t * (QuadraticBranch(row, spinRate) - low));
        }

        private static double LinearBranch(int row, double w) => Linear[row][0] * w + Linear[row][1];

        private static double QuadraticBranch(int row, double w)
        {
            double[] q = Quadratic[row];
            return (q[0] * w + q[1]) * w + q[2];
        }

        private static double Positive(double c) => c > 0 ? c : 0.0;

        /// <inheritdoc />
        public override string ToString() => "ContiTableTennisLift";
    }
}
