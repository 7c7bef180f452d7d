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
        public StepanekDrag()
        {
        }

        /// <summary>The drag coefficient C_D (dimensionless, 0.508 up to 0.508 + 22.053^-0.4 = 0.7981) for these conditions.</summary>
        /// <param name="conditions">The speed, spin rate, radius and spin parameter at this instant.</param>
        /// <remarks>
        /// <see cref="Evaluate"/>'s law, with 1/S formed as s (1/(r |w|)) from the conditions' speed, radius and spin rate
        /// rather than as 1/S (where r |w| is a normal double; otherwise as 1/S): the same value to rounding (measured
        /// within 1 ulp of <see cref="Evaluate"/>'s C_D), and in a flight the reciprocal is taken of the spin alone, off the
        /// speed's path, which makes the full tennis model's RK4 step about 12 % cheaper on .NET (docs/performance.md).
        /// S &lt;= 0 gives the no-spin value 0.508, as there.
        /// </remarks>
        public double DragCoefficient(in AeroConditions conditions) => FromConditions(conditions);

        /// <summary><see cref="DragCoefficient"/>'s arithmetic, shared with the flight kernel and (lane by lane) the ball batch.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static double FromConditions(in AeroConditions conditions)
        {
            if (!(conditions.SpinParameter > 0))
            {
                return 0.508;
            }

            // u = 1/S = s / (r |w|) where r |w| is a normal double (the test depends on the spin only, so it is off the
            // speed's path); elsewhere (r |w| subnormal or past double.MaxValue, where s (1/(r |w|)) would give the wrong
            // limit or inf x 0) 1/S itself, as Evaluate takes it.
            double rw = conditions.Radius * conditions.SpinRate;
            double u = rw >= 2.2250738585072014e-308 && rw <= double.MaxValue ? conditions.Speed * (1.0 / rw) : 1.0 / conditions.SpinParameter;
            return 0.508 + PowMinusTwoFifths(22.053 + 4.196 * (u * u * Math.Sqrt(u)));
        }

        /// <summary>C_D at spin parameter <paramref name="spinParameter"/> (S &lt;= 0 gives the no-spin value 0.508).</summary>
        /// <param name="spinParameter">S = r|w|/s.</param>
        public static double Evaluate(double spinParameter)
        {
            if (!(spinParameter > 0))
            {
                return 0.508;
            }

            // (1/S)^2.5 = u^2 sqrt(u) with u = 1/S: a square root instead of a second Math.Pow, and the ^-0.4 by
            // PowMinusTwoFifths instead of Math.Pow (Pow dominated the model's cost, docs/performance.md). It overflows
            // to +inf for tiny S; inf^-0.4 is 0, the correct limit.
            double u = 1.0 / spinParameter;
            return 0.508 + PowMinusTwoFifths(22.053 + 4.196 * (u * u * Math.Sqrt(u)));
        }

        /// <summary>
        /// x^(-2/5) for x &gt;= 1 (+inf gives 0): the law's Math.Pow(x, -0.4), about twice as cheap and the same on every
        /// runtime (only + - * and bit operations, no library call), within 1.2 ulp of the exact x^(-2/5) over the whole
        /// range (StepanekDragTests sweeps it).
        /// </summary>
        /// <remarks>
        /// <para>Range reduction: x = m 2^e with m in [1, 2), e = 5q + r with r in 0..4, so x^(-2/5) = 2^(-2q) M^(-2/5)
        /// with M = m 2^r in [1, 32). A degree-7 polynomial in s = 2m - 3 (Chebyshev interpolant of m^(-2/5) on [1, 2],
        /// relative error 2.3e-7) times 2^(-2r/5) gives y0 ~ M^(-2/5); one third-order correction on the exact relation
        /// M^2 y^5 = 1 finishes it: with d = 1 - M^2 y0^5, y = y0 (1 + d/5 + 3 d^2/25), error about 0.09 d^3 ~ 1e-19, so
        /// what remains is rounding. The constants need not be exact: the correction absorbs their error; they only
        /// have to be the same everywhere, which literals are.</para>
        /// <para>Math.Pow(x, -0.4) itself computes x to the double nearest -0.4, which is 2.2e-17 below -2/5: it
        /// differs from the exact law by up to 142 ulp at x ~ 1e308 (a spin parameter of 1e-123), while this function
        /// stays within 1.2 ulp of it.</para>
        /// <para>Written for x &gt;= 1 (the law's argument is at least 22.053); a NaN or an x below 1 is not handled.</para>
        /// </remarks>
        /// <param name="x">The argument, &gt;= 1 or +inf.</param>
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
            double s = 2 * m - 3;
            double s2 = s * s;
            double p = (C0 + s * C1) + s2 * (C2 + s * C3) + (s2 * s2) * ((C4 + s * C5) + s2 * (C6 + s * C7));
            double y = p * TwoToMinusTwoFifths[r];
            double big = m * BitConverter.Int64BitsToDouble((long)(1023 + r) << 52); // M = m 2^r, exact
            double a = big * big;
            double y2 = y * y;
            double d = 1 - (a * y) * (y2 * y2);
            y += (y * d) * (0.2 + d * 0.12);
            return y * BitConverter.Int64BitsToDouble((long)(1023 - 2 * q) << 52); // 2^(-2q), exact (q <= 204)
        }

        // m^(-2/5) on [1, 2] in powers of s = 2m - 3: the degree-7 Chebyshev interpolant (relative error 2.3e-7).
        internal const double C0 = 0.8502828422008286;
        internal const double C1 = -0.1133710173698683;
        internal const double C2 = 0.026458296327941805;
        internal const double C3 = -0.007055774091898004;
        internal const double C4 = 0.0019738696706810277;
        internal const double C5 = -0.000578542072451893;
        internal const double C6 = 0.0002139579862423524;
        internal const double C7 = -6.547004208679041E-05;

        // 2^(-2r/5), r = 0..4 (the doubles nearest; the correction step absorbs their rounding).
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
        public StepanekLift()
        {
        }

        /// <inheritdoc />
        public double LiftCoefficient(in AeroConditions conditions) => Evaluate(conditions.TransverseSpinParameter);

        /// <summary>C_L at transverse spin parameter <paramref name="spinParameter"/> (0 for S &lt;= 0).</summary>
        /// <param name="spinParameter">S_perp = r|w x v_hat|/s.</param>
        public static double Evaluate(double spinParameter)
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
