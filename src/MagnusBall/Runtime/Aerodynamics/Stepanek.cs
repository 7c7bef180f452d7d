using System;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Stepanek's spin-dependent tennis drag, C_D = 0.508 + (22.053 + 4.196 (1/S)^2.5)^-0.4, with S = r|w|/s.
    /// </summary>
    /// <remarks>
    /// Source: Stepanek (1988), "The aerodynamics of tennis balls - the topspin lob", Am. J. Phys. 56:138,
    /// as used by Klvana (1998) and Cross. One secondary copy prints 22.503 for 22.053; 22.053 is used here.
    /// At S = 0 the law tends to 0.508; as S grows it rises toward 0.508 + 22.053^-0.4 = 0.798.
    /// </remarks>
    public sealed class StepanekDrag : IDragModel
    {
        /// <summary>The shared instance (the law has no parameters).</summary>
        public static StepanekDrag Instance { get; } = new StepanekDrag();

        /// <summary>
        /// Creates the law. It holds no state, so every instance gives the same numbers as <see cref="Instance"/>
        /// (which the presets and the flight kernel use; the kernel specialises on the type, not the instance).
        /// </summary>
        internal StepanekDrag()
        {
        }

        /// <summary>The drag coefficient C_D (dimensionless, 0.508 up to 0.508 + 22.053^-0.4 = 0.7981) for these conditions.</summary>
        /// <param name="conditions">The speed, spin rate, radius and spin parameter at this instant.</param>
        /// <remarks>
        /// <see cref="Evaluate"/>'s law, with 1/S formed as s (1/(r |w|)) from the conditions' speed, radius and spin rate
        /// rather than as 1/S (where r |w| is a normal double; otherwise as 1/S): the same value to rounding (measured
        /// within 2 ulp of <see cref="Evaluate"/>'s C_D, 5.5 by analysis), and in a flight the reciprocal is taken of the spin
        /// alone, off the speed's path, which made the full tennis model's RK4 step about 12 % cheaper on .NET
        /// (docs/performance.md). C_D - 0.508 comes from a table of the law in z = Kappa u^2 where z lies in [2^-44, 2^44)
        /// (<see cref="TryTable"/>), from <see cref="PowMinusTwoFifths"/> elsewhere; within 4.25 ulp of the exact law.
        /// S &lt;= 0 gives the no-spin value 0.508, as there.
        /// </remarks>
        double IDragModel.DragCoefficient(in AeroConditions conditions) => FromConditions(conditions);

        /// <summary><see cref="IDragModel.DragCoefficient"/>'s arithmetic, shared with the flight kernel and (lane by lane) the ball batch.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static double FromConditions(in AeroConditions conditions) =>
            0.508 + SpinPart(conditions.Speed, conditions.SpinRate, conditions.Radius, conditions.SpinParameter); // S <= 0: 0.508 + 0

        /// <summary>
        /// C_D - 0.508 = (22.053 + 4.196 (1/S)^2.5)^-0.4 (0 for S &lt;= 0) from the four numbers it reads: <see cref="FromConditions"/>
        /// without the constant, which the flight kernel's folded form adds to the drag by itself (FlightKernel's
        /// TryFoldedRates, which passes the numbers in registers).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static double SpinPart(double speed, double spinRate, double radius, double spinParameter)
        {
            if (!(spinParameter > 0))
            {
                return 0;
            }

            // u = 1/S = s / (r |w|) where r |w| is a normal double (the test depends on the spin only, so it is off the
            // speed's path); elsewhere (r |w| subnormal or past double.MaxValue, where s (1/(r |w|)) would give the wrong
            // limit or inf x 0) 1/S itself, as Evaluate takes it.
            double rw = radius * spinRate;
            double u = rw >= 2.2250738585072014e-308 && rw <= double.MaxValue ? speed * (1.0 / rw) : 1.0 / spinParameter;
            return OfRatio(u);
        }

        /// <summary>
        /// <see cref="SpinPart"/> as the flight kernel's folded form takes it (FlightKernel's TryFoldedRates), from
        /// <paramref name="z"/> = Kappa s^2 / (r |w|)^2 formed from the squared speed, so that the speed's square root is not on
        /// the drag's path: the table's value where z lies in its range, elsewhere <see cref="SpinPart"/> with the spin
        /// parameter r |w| / s formed here (as the kernel's general path forms it), so that no division by the speed is made
        /// where the table answers. The ball batch calls it lane by lane, so both give the same bits.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static double SpinPartOfSquare(double z, double speed, double spinRate, double radius) =>
            TryTable(z, out double g) ? g : SpinPart(speed, spinRate, radius, spinRate * (radius / speed));

        /// <summary>
        /// G = C_D - 0.508 at u = 1/S: the table at z = Kappa u^2 where that lies in its range (<see cref="TryTable"/>), else
        /// the power of the argument (<see cref="PowMinusTwoFifths"/>). Within 3.5 ulp of the exact law at u inside the table and 4.25
        /// outside it (StepanekTableTests; 2.63 ulp the worst found).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static double OfRatio(double u) =>
            TryTable(StepanekTable.Kappa * (u * u), out double g) ? g : PowMinusTwoFifths(Argument(u));

        /// <summary>
        /// G = (22.053 + 4.196 u^2.5)^-0.4 from z = Kappa u^2 (Kappa = (4.196/22.053)^(4/5), so 4.196 u^2.5 = 22.053 z^(5/4)
        /// up to Kappa's rounding, which the table includes): false, and <paramref name="g"/> 0, outside z in [2^-44, 2^44).
        /// </summary>
        /// <remarks>
        /// <para>One polynomial per quarter binade of z (StepanekTable, written by tools/stepanek-table.py): z = 2^e (1 + j/4 +
        /// 1/8 + t) with t in [-1/8, 1/8), G = c0 + c1 t + ... + c15 t^15, the degree-15 Chebyshev interpolant of the exact law
        /// on that quarter (computed in 50-digit arithmetic; its own error is below 1e-19 relative), summed by Estrin's scheme.
        /// The row and t come from z's bits; no square root, no division, no range reduction of a power. The exact G is a
        /// function of u^2, so the flight kernel forms z from the squared speed and the speed's square root runs beside the
        /// table's polynomial instead of before it (docs/performance.md).</para>
        /// <para>Within 2.28 ulp of the exact G(z), the worst of 2e5 points the generator checked against 50-digit values
        /// (StepanekTableTests checks 14 points of every row and that one in exact integer arithmetic, and asserts 2.5 ulp).
        /// Below 2^-44, G differs from its limit 22.053^-0.4 by less than 2^-56 relative, and above 2^44 it is
        /// 22.053^-0.4 z^-1/2 to rounding; there the power of the argument (<see cref="PowMinusTwoFifths"/>) takes over.</para>
        /// </remarks>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static bool TryTable(double z, out double g)
        {
            long bits = BitConverter.DoubleToInt64Bits(z);
            long row = TableRow(bits);
            if ((ulong)row >= StepanekTable.Rows)
            {
                g = 0;
                return false; // z outside [2^-44, 2^44), 0, subnormal, negative, inf or NaN
            }

            g = TablePolynomial(bits, row);
            return true;
        }

        /// <summary>
        /// <see cref="TryTable"/> without a branch, for RK4's straight-line form under Mono (FlightKernel): the same G where
        /// z lies in the table, with <paramref name="inTable"/> true; elsewhere the first row's polynomial at z's mantissa (a
        /// finite number of no meaning) with <paramref name="inTable"/> false.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static double TableWithoutBranch(double z, out bool inTable)
        {
            long bits = BitConverter.DoubleToInt64Bits(z);
            long row = TableRow(bits);
            long inRange = ((row - StepanekTable.Rows) & ~row) >> 63; // all ones where 0 <= row < Rows, else 0
            inTable = inRange != 0;
            return TablePolynomial(bits, row & inRange);
        }

        // The row of z's quarter binade: 4 (biased exponent) + the top two bits of the mantissa, from the table's lowest.
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static long TableRow(long bits) => (bits >> 50) - ((1023L + StepanekTable.LowestBinade) << 2);

        // The row's polynomial at t, z's position in its quarter binade (exact), by Estrin's scheme.
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double TablePolynomial(long bits, long row)
        {
            double t = BitConverter.Int64BitsToDouble((bits & 0x0003_FFFF_FFFF_FFFFL) | 0x3FF0_0000_0000_0000L) - 1.125; // exact
            double[] c = StepanekTable.Coefficients;
            int i = (int)row * StepanekTable.Stride;
            double t2 = t * t, t4 = t2 * t2, t8 = t4 * t4;
            double p0 = (c[i] + t * c[i + 1]) + t2 * (c[i + 2] + t * c[i + 3]);
            double p1 = (c[i + 4] + t * c[i + 5]) + t2 * (c[i + 6] + t * c[i + 7]);
            double p2 = (c[i + 8] + t * c[i + 9]) + t2 * (c[i + 10] + t * c[i + 11]);
            double p3 = (c[i + 12] + t * c[i + 13]) + t2 * (c[i + 14] + t * c[i + 15]);
            return (p0 + t4 * p1) + t8 * (p2 + t4 * p3);
        }

        // 22.053 + 4.196 u^2.5 as (4.196 u^2) sqrt(u): the product 4.196 u^2 is formed while the square root runs.
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double Argument(double u) => 22.053 + 4.196 * (u * u) * Math.Sqrt(u);

        /// <summary>C_D at spin parameter <paramref name="spinParameter"/> (S &lt;= 0 gives the no-spin value 0.508).</summary>
        /// <param name="spinParameter">S = r|w|/s.</param>
        internal static double Evaluate(double spinParameter)
        {
            if (!(spinParameter > 0))
            {
                return 0.508;
            }

            // u = 1/S; G from the table at z = Kappa u^2, or where z lies outside it as (22.053 + 4.196 u^2 sqrt(u))^-0.4 by
            // PowMinusTwoFifths instead of Math.Pow (Pow dominated the model's cost, docs/performance.md). u^2.5 overflows
            // to +inf for tiny S; inf^-0.4 is 0, the correct limit.
            double u = 1.0 / spinParameter;
            return 0.508 + OfRatio(u);
        }

        /// <summary>
        /// x^(-2/5) for x &gt;= 1 (+inf gives 0): the law's Math.Pow(x, -0.4) where its table (<see cref="TryTable"/>) does not
        /// reach (u = 1/S outside about [4.6e-7, 8.2e6]), and the DP54 controller's power; cheaper than Math.Pow (docs/performance.md)
        /// and the same on every runtime (only + - * and bit operations, no library call), within 2.05 ulp of the exact x^(-2/5)
        /// over the whole range (the worst point found; StepanekPowTests sweeps it and checks that point).
        /// </summary>
        /// <remarks>
        /// <para>Range reduction: x = m 2^e with m in [1, 2), e = 5q + r with r in 0..4, so x^(-2/5) = 2^(-2q) 2^(-2r/5)
        /// m^(-2/5). m^(-2/5) is a degree-23 polynomial in t = m - 3/2 (the Chebyshev interpolant on [1, 2], computed in
        /// 60-digit arithmetic and rounded to doubles; its own error is below 4e-19, so what remains is rounding), summed as
        /// C0 + t R(t) with R by Estrin's scheme: pairs, then quadruples, ..., so the terms run side by side and the chain is
        /// about ten operations long where Horner's would be 46. The earlier form (a degree-7 polynomial refined by a
        /// third-order correction on M^2 y^5 = 1) was within 1.2 ulp, but its correction lay on RK4's dependent chain; this
        /// one is about 2 ns shorter in a dependent chain of calls (17.1 against 18.9 ns, docs/performance.md).</para>
        /// <para>Math.Pow(x, -0.4) itself computes x to the double nearest -0.4, which is 2.2e-17 below -2/5: it
        /// differs from the exact law by up to 142 ulp at x ~ 1e308 (a spin parameter of 1e-123), while this function
        /// stays within 2.05 ulp of it.</para>
        /// <para>Written for x &gt;= 1 (the law's argument is at least 22.053); a NaN or an x below 1 is not handled.</para>
        /// </remarks>
        /// <param name="x">The argument, &gt;= 1 or +inf.</param>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static double PowMinusTwoFifths(double x)
        {
            if (!(x <= double.MaxValue))
            {
                return 0; // +inf: the limit (the law at S -> 0)
            }

            long bits = BitConverter.DoubleToInt64Bits(x);
            int e = (int)(bits >> 52) - 1023; // x >= 1: the sign bit is 0 and e >= 0
            double m = BitConverter.Int64BitsToDouble((bits & 0x000F_FFFF_FFFF_FFFFL) | 0x3FF0_0000_0000_0000L);
            int q = e / 5;
            int r = e - 5 * q;
            double t = m - 1.5; // exact
            // 2^(-2r/5) 2^(-2q) is exact (a power of two times a normal double, itself normal), so multiplying by it once
            // gives the bits of multiplying by its two factors in turn, one product sooner (the polynomial is the late operand).
            double scale = TwoToMinusTwoFifths[r] * BitConverter.Int64BitsToDouble((long)(1023 - 2 * q) << 52); // 2^(-2q), q <= 204
            return (C0 + t * Rest(t)) * scale;
        }

        // R(t) of m^(-2/5) = C0 + t R(t) at t = m - 3/2, by Estrin's scheme.
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double Rest(double t)
        {
            double t2 = t * t, t4 = t2 * t2, t8 = t4 * t4, t16 = t8 * t8;
            double q0 = (D0 + t * D1) + t2 * (D2 + t * D3);
            double q1 = (D4 + t * D5) + t2 * (D6 + t * D7);
            double q2 = (D8 + t * D9) + t2 * (D10 + t * D11);
            double q3 = (D12 + t * D13) + t2 * (D14 + t * D15);
            double q4 = (D16 + t * D17) + t2 * (D18 + t * D19);
            double q5 = (D20 + t * D21) + t2 * D22;
            return ((q0 + t4 * q1) + t8 * (q2 + t4 * q3)) + t16 * (q4 + t4 * q5);
        }

        // m^(-2/5) on [1, 2] = C0 + t (D0 + D1 t + ... + D22 t^22) with t = m - 3/2: the degree-23 Chebyshev interpolant
        // (error below 4e-19), computed in powers of s = 2t = 2m - 3 and written here for t, each coefficient times the
        // power of two that makes the two the same numbers (D_k = c_(k+1) 2^(k+1)): exact, so the sum is the same, bit for bit,
        // one operation shorter (t = m - 1.5 is exact).
        private const double C0 = 0.8502830004171938;
        private const double D0 = -0.22674213344458505;
        private const double D1 = 0.10581299560747306;
        private const double D2 = -0.05643359765731898;
        private const double D3 = 0.03197903867247056;
        private const double D4 = -0.01876103602118207;
        private const double D5 = 0.011256621613470345;
        private const double D6 = -0.006861178888242232;
        private const double D7 = 0.004231060285063281;
        private const double D8 = -0.0026326597320797005;
        private const double D9 = 0.001649800766625627;
        private const double D10 = -0.0010398744364568877;
        private const double D11 = 0.0006585775108352798;
        private const double D12 = -0.00041878760521706277;
        private const double D13 = 0.0002673178211823087;
        private const double D14 = -0.00017108440349645348;
        private const double D15 = 0.00010920006130503545;
        private const double D16 = -7.022615884999406e-05;
        private const double D17 = 4.767903425507203e-05;
        private const double D18 = -3.0794816575262266e-05;
        private const double D19 = 1.348930395338362e-05;
        private const double D20 = -8.715802210227895e-06;
        private const double D21 = 1.5441405801522207e-05;
        private const double D22 = -1.0039743760367213e-05;

        // 2^(-2r/5) for r = 0..4 (the doubles nearest).
        private static readonly double[] TwoToMinusTwoFifths = { 1.0, 0.757858283255199, 0.5743491774985175, 0.43527528164806206, 0.32987697769322355 };

        /// <inheritdoc />
        public override string ToString() => "StepanekDrag";
    }

    /// <summary>
    /// Stepanek's spin-dependent tennis lift, C_L = 1/(2.022 + 0.981/S_perp), with S_perp = r|w x v_hat|/s.
    /// </summary>
    /// <remarks>
    /// Source: Stepanek (1988), Am. J. Phys. 56:138, as used by Klvana (1998) and Cross. C_L is 0 at S_perp = 0
    /// and tends to 1/2.022 = 0.495 as S_perp grows.
    /// </remarks>
    public sealed class StepanekLift : ILiftModel
    {
        /// <summary>The shared instance (the law has no parameters).</summary>
        public static StepanekLift Instance { get; } = new StepanekLift();

        /// <summary>
        /// Creates the law. It holds no state, so every instance gives the same numbers as <see cref="Instance"/>
        /// (which the presets and the flight kernel use; the kernel specialises on the type, not the instance).
        /// </summary>
        internal StepanekLift()
        {
        }

        /// <inheritdoc />
        double ILiftModel.LiftCoefficient(in AeroConditions conditions) => Evaluate(conditions.TransverseSpinParameter);

        /// <summary>C_L at transverse spin parameter <paramref name="spinParameter"/> (0 for S &lt;= 0).</summary>
        /// <param name="spinParameter">S_perp = r|w x v_hat|/s.</param>
        internal static double Evaluate(double spinParameter)
        {
            if (!(spinParameter > 0))
            {
                return 0;
            }

            // Divided through by S for huge S, where 2.022 S would overflow.
            return spinParameter < 1e300 ? spinParameter / (2.022 * spinParameter + 0.981) : 1.0 / (2.022 + 0.981 / spinParameter);
        }

        /// <inheritdoc />
        public override string ToString() => "StepanekLift";
    }
}
