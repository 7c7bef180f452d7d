// PortableMath: Exp, Log and Pow, with the double-double helpers (TwoSum, TwoProduct, ...) they share with the
// reductions. Sin, Cos, Atan and Atan2 with their kernels and argument reductions are in PortableMath.Trig.cs.
using System;

namespace MagnusBall
{
    /// <summary>
    /// The transcendental functions the library's simulation uses, computed only from IEEE 754 + - * / and
    /// <see cref="Math.Sqrt"/> (all exactly rounded on every conforming runtime), exact operations (comparisons,
    /// <see cref="Math.Abs(double)"/>, <see cref="Math.Floor(double)"/>, bit moves between double and long) and
    /// integer arithmetic. <see cref="Math"/>'s own Sin, Exp, Pow, ... come from each platform's C library or from
    /// the JIT (Mono compiles Math.Sin to x87 fsin), so they can differ by an ulp between a game's players; these
    /// give the same bits wherever the runtime does not contract a*b+c into a fused multiply-add.
    /// </summary>
    /// <remarks>
    /// Algorithms: the kernels and reductions of Sun's fdlibm (the same minimax polynomials; its Cody-Waite
    /// splits of pi/2 and ln 2), with two additions: arguments of Sin and Cos beyond 2^20 pi/2 are reduced
    /// exactly by integer Payne-Hanek reduction against 1,280 bits of 2/pi, and <see cref="Pow"/> evaluates
    /// y ln x in double-double (Dekker products by Veltkamp splitting, no FMA) so that its error stays below
    /// about one ulp even where exp magnifies the error of the logarithm 700-fold. Accuracy against
    /// <see cref="Math"/> over the whole input range, as measured by PortableMathTests (docs/determinism.md):
    /// Sin, Cos, Atan2, Exp, Log within 1 ulp; Pow within 1 ulp. Special values (NaN, infinities, signed zeros)
    /// follow C99 Annex F, as <see cref="Math"/> does on .NET Core 3.0 and later.
    /// </remarks>
    internal static partial class PortableMath
    {
        // ---- exp (fdlibm e_exp.c) ----
        private const double Ln2Hi = 6.93147180369123816490e-01; // ln 2, first 32 bits: k * Ln2Hi is exact for |k| < 2^21
        private const double Ln2Lo = 1.90821492927058770002e-10; // ln 2 - Ln2Hi
        private const double InvLn2 = 1.44269504088896338700e+00;
        private const double P1 = 1.66666666666666019037e-01;
        private const double P2 = -2.77777777770155933842e-03;
        private const double P3 = 6.61375632143793436117e-05;
        private const double P4 = -1.65339022054652515390e-06;
        private const double P5 = 4.13813679705723846039e-08;
        private const double ExpOverflow = 7.09782712893383973096e+02;  // above: +infinity
        private const double ExpUnderflow = -7.45133219101941108420e+02; // below: +0

        // ---- log in double-double ----
        private const double Ln2Hi53 = 0.6931471805599453;      // ln 2 rounded to double
        private const double Ln2Lo53 = 2.3190468138462996e-17;  // ln 2 - Ln2Hi53
        private const double ThirdHi = 0.3333333333333333;
        private const double ThirdLo = 1.850371707708594e-17;   // 1/3 - ThirdHi
        private const double Sqrt2 = 1.4142135623730951;

        /// <summary>e^x.</summary>
        public static double Exp(double x)
        {
            if (double.IsNaN(x))
            {
                return x;
            }

            if (x > ExpOverflow)
            {
                return double.PositiveInfinity;
            }

            if (x < ExpUnderflow)
            {
                return 0.0;
            }

            return ExpCore(x, 0.0);
        }

        /// <summary>The natural logarithm of x (NaN below 0, -infinity at 0).</summary>
        public static double Log(double x)
        {
            if (!(x > 0) || double.IsPositiveInfinity(x))
            {
                return x == 0 ? double.NegativeInfinity : x > 0 ? x : double.NaN;
            }

            LogCore(x, out double hi, out double lo);
            return hi + lo;
        }

        /// <summary>x^y, with the special cases of C99 (and of <see cref="Math.Pow"/>).</summary>
        public static double Pow(double x, double y)
        {
            if (y == 0 || x == 1)
            {
                return 1.0;
            }

            if (double.IsNaN(x) || double.IsNaN(y))
            {
                return double.NaN;
            }

            double ax = Math.Abs(x);
            if (double.IsInfinity(y))
            {
                if (ax == 1)
                {
                    return 1.0;
                }

                return (ax > 1) == (y > 0) ? double.PositiveInfinity : 0.0;
            }

            bool yIsInteger = Math.Floor(y) == y;
            bool yIsOdd = yIsInteger && Math.Abs(y) < 9007199254740992.0 && Math.Floor(y * 0.5) * 2 != y;
            bool negative = x < 0 || (x == 0 && 1 / x < 0); // sign bit (x is not NaN here)
            if (x == 0 || double.IsInfinity(x))
            {
                bool large = double.IsInfinity(x) == (y > 0); // |x|^y is infinite
                double magnitude = large ? double.PositiveInfinity : 0.0;
                return negative && yIsOdd ? -magnitude : magnitude;
            }

            if (x < 0 && !yIsInteger)
            {
                return double.NaN;
            }

            double result = ax == 1 ? 1.0 : PositivePow(ax, y); // x = -1, y an integer (of any size)
            return x < 0 && yIsOdd ? -result : result;
        }

        // ---------------------------------------------------------------- exp

        /// <summary>e^(hi + lo) for |lo| much smaller than ulp(hi) and hi inside (ExpUnderflow, ExpOverflow].</summary>
        private static double ExpCore(double hi, double lo)
        {
            double k = Math.Floor(hi * InvLn2 + 0.5);
            double rHi = hi - k * Ln2Hi;   // exact (Sterbenz; k * Ln2Hi exact)
            double rLo = k * Ln2Lo - lo;   // the reduced argument is rHi - rLo
            double r = rHi - rLo;
            double t = r * r;
            double c = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))));
            double e = 1.0 - ((rLo - (r * c) / (2.0 - c)) - rHi);
            return Scale(e, (int)k);
        }

        /// <summary>v * 2^k, rounded once.</summary>
        private static double Scale(double v, int k)
        {
            if (k > 1023)
            {
                return v * PowerOfTwo(1023) * PowerOfTwo(k - 1023);
            }

            if (k < -1022)
            {
                return v * PowerOfTwo(k + 1000) * PowerOfTwo(-1000); // the first product is exact; the second rounds once
            }

            return v * PowerOfTwo(k);
        }

        private static double PowerOfTwo(int k) => BitConverter.Int64BitsToDouble((long)(k + 1023) << 52);

        private static int Exponent(double v) => (int)((BitConverter.DoubleToInt64Bits(v) >> 52) & 0x7FF);

        // ---------------------------------------------------------------- log, pow

        /// <summary>ln x = hi + lo (|lo| &lt;= ulp(hi)/2, error about 1e-20 relative) for finite x &gt; 0.</summary>
        private static void LogCore(double x, out double hi, out double lo)
        {
            int k = 0;
            if (x < 2.2250738585072014e-308)
            {
                x *= 18014398509481984.0; // 2^54: subnormal to normal, exactly
                k = -54;
            }

            long bits = BitConverter.DoubleToInt64Bits(x);
            k += (int)((bits >> 52) & 0x7FF) - 1023;
            double m = BitConverter.Int64BitsToDouble((bits & 0x000FFFFFFFFFFFFFL) | 0x3FF0000000000000L); // [1, 2)
            if (m > Sqrt2)
            {
                m *= 0.5;
                k++;
            }

            // ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.1716: s in double-double.
            double f = m - 1.0;                       // exact (Sterbenz)
            double uHi = 2.0 + f;
            double uLo = f - (uHi - 2.0);             // 2 + f = uHi + uLo exactly
            double sHi = f / uHi;
            TwoProduct(sHi, uHi, out double p, out double pe);
            double sLo = (((f - p) - pe) - sHi * uLo) / uHi;

            // 2 atanh(s) = 2s + 2 s^3 (1/3 + s^2/5 + s^4/7 + ...), the 1/3 term and s^3 in double-double.
            double z = sHi * sHi;
            double q = z * (1.0 / 5 + z * (1.0 / 7 + z * (1.0 / 9 + z * (1.0 / 11 + z * (1.0 / 13 + z * (1.0 / 15
                + z * (1.0 / 17 + z * (1.0 / 19 + z * (1.0 / 21 + z * (1.0 / 23 + z * (1.0 / 25 + z * (1.0 / 27))))))))))));
            TwoSum(ThirdHi, q, out double iHi, out double iLo);
            iLo += ThirdLo;
            TwoProduct(sHi, sHi, out double s2Hi, out double s2Lo);
            s2Lo += 2.0 * sHi * sLo;
            Multiply(s2Hi, s2Lo, sHi, sLo, out double s3Hi, out double s3Lo);
            Multiply(s3Hi, s3Lo, iHi, iLo, out double tHi, out double tLo);
            TwoSum(sHi, tHi, out double lHi, out double lLo);
            lLo += sLo + tLo;
            lHi *= 2.0;
            lLo *= 2.0;

            // + k ln 2 in double-double.
            TwoProduct(k, Ln2Hi53, out double kHi, out double kLo);
            kLo += k * Ln2Lo53;
            TwoSum(kHi, lHi, out hi, out double e);
            e += kLo + lLo;
            FastTwoSum(hi, e, out hi, out lo);
        }

        /// <summary>x^y for finite x &gt; 0, finite y != 0: e^(y ln x) with y ln x in double-double.</summary>
        private static double PositivePow(double x, double y)
        {
            LogCore(x, out double lHi, out double lLo);
            double estimate = y * lHi;
            if (estimate > 710)
            {
                return double.PositiveInfinity;
            }

            if (estimate < -746)
            {
                return 0.0;
            }

            TwoProduct(y, lHi, out double hi, out double lo);
            lo += y * lLo;
            FastTwoSum(hi, lo, out hi, out lo);
            if (hi > ExpOverflow)
            {
                return double.PositiveInfinity;
            }

            if (hi < ExpUnderflow)
            {
                return 0.0;
            }

            return ExpCore(hi, lo);
        }

        // ---------------------------------------------------------------- double-double arithmetic (no FMA)

        private static void TwoSum(double a, double b, out double s, out double e)
        {
            s = a + b;
            double bb = s - a;
            e = (a - (s - bb)) + (b - bb);
        }

        private static void FastTwoSum(double a, double b, out double s, out double e) // |a| >= |b| or a == 0
        {
            s = a + b;
            e = b - (s - a);
        }

        private static void Split(double a, out double hi, out double lo)
        {
            double t = 134217729.0 * a; // 2^27 + 1 (Veltkamp)
            hi = t - (t - a);
            lo = a - hi;
        }

        /// <summary>a * b = p + e exactly (Dekker), for |a|, |b| below about 2^995.</summary>
        private static void TwoProduct(double a, double b, out double p, out double e)
        {
            p = a * b;
            Split(a, out double aHi, out double aLo);
            Split(b, out double bHi, out double bLo);
            e = ((aHi * bHi - p) + aHi * bLo + aLo * bHi) + aLo * bLo;
        }

        private static void Multiply(double aHi, double aLo, double bHi, double bLo, out double hi, out double lo)
        {
            TwoProduct(aHi, bHi, out double p, out double e);
            e += aHi * bLo + aLo * bHi;
            FastTwoSum(p, e, out hi, out lo);
        }
    }
}
