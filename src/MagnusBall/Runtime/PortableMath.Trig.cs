// PortableMath, part: Sin, Cos, Atan and Atan2: fdlibm's kernels (KernelSin, KernelCos) and argument reduction
// (Reduce: Cody-Waite; ReduceLarge: Payne-Hanek against 1,280 bits of 2/pi), with their constants. Exp, Log, Pow and the
// double-double helpers are in PortableMath.cs.
using System;

namespace MagnusBall
{
    internal static partial class PortableMath
    {
        // ---- sin, cos (fdlibm k_sin.c, k_cos.c, e_rem_pio2.c) ----
        private const double S1 = -1.66666666666666324348e-01;

        private const double S2 = 8.33333333332248946124e-03;

        private const double S3 = -1.98412698298579493134e-04;

        private const double S4 = 2.75573137070700676789e-06;

        private const double S5 = -2.50507602534068634195e-08;

        private const double S6 = 1.58969099521155010221e-10;

        private const double C1 = 4.16666666666666019037e-02;

        private const double C2 = -1.38888888888741095749e-03;

        private const double C3 = 2.48015872894767294178e-05;

        private const double C4 = -2.75573143513906633035e-07;

        private const double C5 = 2.08757232129817482790e-09;

        private const double C6 = -1.13596475577881948265e-11;

        private const double InvPio2 = 6.36619772367581382433e-01;

        private const double Pio2_1 = 1.57079632673412561417e+00;  // first 33 bits of pi/2

        private const double Pio2_1t = 6.07710050650619224932e-11; // pi/2 - Pio2_1

        private const double Pio2_2 = 6.07710050630396597660e-11;  // second 33 bits

        private const double Pio2_2t = 2.02226624879595063154e-21;

        private const double Pio2_3 = 2.02226624871116645580e-21;  // third 33 bits

        private const double Pio2_3t = 8.47842766036889956997e-32;

        private const double Pio2Hi = 1.5707963267948966;

        private const double Pio2Lo = 6.123233995736766e-17;

        private const double MediumReduction = 1647099.3291652855; // 2^20 pi/2: above, Payne-Hanek

        // 2/pi to 1,280 bits, most significant word first (tools/portable-math-constants.py prints them).
        private static readonly ulong[] TwoOverPi =
        {
            0xA2F9836E4E441529UL, 0xFC2757D1F534DDC0UL, 0xDB6295993C439041UL, 0xFE5163ABDEBBC561UL, 0xB7246E3A424DD2E0UL,
            0x06492EEA09D1921CUL, 0xFE1DEB1CB129A73EUL, 0xE88235F52EBB4484UL, 0xE99C7026B45F7E41UL, 0x3991D639835339F4UL,
            0x9C845F8BBDF9283BUL, 0x1FF897FFDE05980FUL, 0xEF2F118B5A0A6D1FUL, 0x6D367ECF27CB09B7UL, 0x4F463F669E5FEA2DUL,
            0x7527BAC7EBE5F17BUL, 0x3D0739F78A5292EAUL, 0x6BFB5FB11F8D5D08UL, 0x56033046FC7B6BABUL, 0xF0CFBC209AF4361DUL,
        };

        // ---- atan (fdlibm s_atan.c, e_atan2.c) ----
        private static readonly double[] AtanHi = { 4.63647609000806093515e-01, 7.85398163397448278999e-01, 9.82793723247329054082e-01, 1.57079632679489655800e+00 };

        private static readonly double[] AtanLo = { 2.26987774529616870924e-17, 3.06161699786838301793e-17, 1.39033110312309984516e-17, 6.12323399573676603587e-17 };

        private const double AT0 = 3.33333333333329318027e-01;

        private const double AT1 = -1.99999999998764832476e-01;

        private const double AT2 = 1.42857142725034663711e-01;

        private const double AT3 = -1.11111104054623557880e-01;

        private const double AT4 = 9.09088713343650656196e-02;

        private const double AT5 = -7.69187620504482999495e-02;

        private const double AT6 = 6.66107313738753120669e-02;

        private const double AT7 = -5.83357013379057348645e-02;

        private const double AT8 = 4.97687799461593236017e-02;

        private const double AT9 = -3.65315727442169155270e-02;

        private const double AT10 = 1.62858201153657823623e-02;

        private const double Pi = 3.1415926535897931160E+00;

        private const double PiLo = 1.2246467991473531772E-16; // pi - Pi

        /// <summary>The sine of x (radians); NaN for infinities.</summary>
        public static double Sin(double x)
        {
            if (Math.Abs(x) <= 7.85398163397448278999e-01)
            {
                return Math.Abs(x) < 7.450580596923828e-09 ? x : KernelSin(x, 0, false); // |x| < 2^-27: sin x rounds to x
            }

            if (double.IsNaN(x) || double.IsInfinity(x))
            {
                return double.NaN;
            }

            int n = Reduce(x, out double y0, out double y1);
            switch (n & 3)
            {
                case 0: return KernelSin(y0, y1, true);
                case 1: return KernelCos(y0, y1);
                case 2: return -KernelSin(y0, y1, true);
                default: return -KernelCos(y0, y1);
            }
        }

        /// <summary>The cosine of x (radians); NaN for infinities.</summary>
        public static double Cos(double x)
        {
            if (Math.Abs(x) <= 7.85398163397448278999e-01)
            {
                return Math.Abs(x) < 7.450580596923828e-09 ? 1.0 : KernelCos(x, 0); // |x| < 2^-27: cos x rounds to 1
            }

            if (double.IsNaN(x) || double.IsInfinity(x))
            {
                return double.NaN;
            }

            int n = Reduce(x, out double y0, out double y1);
            switch (n & 3)
            {
                case 0: return KernelCos(y0, y1);
                case 1: return -KernelSin(y0, y1, true);
                case 2: return -KernelCos(y0, y1);
                default: return KernelSin(y0, y1, true);
            }
        }

        /// <summary>The arctangent of x, in [-pi/2, pi/2].</summary>
        public static double Atan(double x)
        {
            if (double.IsNaN(x))
            {
                return x;
            }

            double ax = Math.Abs(x);
            if (ax >= 7.378697629483821e19) // 2^66: atan rounds to +-pi/2
            {
                return x > 0 ? AtanHi[3] + AtanLo[3] : -AtanHi[3] - AtanLo[3];
            }

            int id;
            if (ax < 0.4375)
            {
                if (ax < 3.725290298461914e-09) // 2^-28: atan x rounds to x
                {
                    return x;
                }

                id = -1;
            }
            else if (ax < 1.1875)
            {
                if (ax < 0.6875)
                {
                    id = 0;
                    ax = (2.0 * ax - 1.0) / (2.0 + ax);
                }
                else
                {
                    id = 1;
                    ax = (ax - 1.0) / (ax + 1.0);
                }
            }
            else if (ax < 2.4375)
            {
                id = 2;
                ax = (ax - 1.5) / (1.0 + 1.5 * ax);
            }
            else
            {
                id = 3;
                ax = -1.0 / ax;
            }

            double z = ax * ax;
            double w = z * z;
            double s1 = z * (AT0 + w * (AT2 + w * (AT4 + w * (AT6 + w * (AT8 + w * AT10)))));
            double s2 = w * (AT1 + w * (AT3 + w * (AT5 + w * (AT7 + w * AT9))));
            if (id < 0)
            {
                return x - x * (s1 + s2); // here ax == |x| and the sign rides on x
            }

            double r = AtanHi[id] - ((ax * (s1 + s2) - AtanLo[id]) - ax);
            return x < 0 ? -r : r;
        }

        /// <summary>The angle of the point (x, y) from the +x axis, in [-pi, pi], with C99's special cases.</summary>
        public static double Atan2(double y, double x)
        {
            if (double.IsNaN(x) || double.IsNaN(y))
            {
                return double.NaN;
            }

            if (x == 1.0)
            {
                return Atan(y);
            }

            bool yNegative = y < 0 || (y == 0 && 1 / y < 0);
            bool xNegative = x < 0 || (x == 0 && 1 / x < 0);
            if (y == 0)
            {
                return !xNegative ? y : yNegative ? -Pi - PiLo : Pi + PiLo;
            }

            if (x == 0)
            {
                return yNegative ? -Pio2Hi - Pio2Lo : Pio2Hi + Pio2Lo;
            }

            if (double.IsInfinity(x))
            {
                double angle = double.IsInfinity(y)
                    ? (xNegative ? 3.0 * 7.85398163397448278999e-01 : 7.85398163397448278999e-01)
                    : (xNegative ? Pi + PiLo : 0.0);
                return yNegative ? -angle : angle;
            }

            if (double.IsInfinity(y))
            {
                return yNegative ? -Pio2Hi - Pio2Lo : Pio2Hi + Pio2Lo;
            }

            int k = Exponent(y) - Exponent(x);
            double z;
            if (k > 60)
            {
                z = Pio2Hi + 0.5 * PiLo; // |y/x| > 2^60
            }
            else if (xNegative && k < -60)
            {
                z = 0.0; // |y/x| < 2^-60 and x < 0
            }
            else
            {
                z = Atan(Math.Abs(y / x));
            }

            if (!xNegative)
            {
                return yNegative ? -z : z;
            }

            double fromPi = Pi - (z - PiLo);
            return yNegative ? -fromPi : fromPi;
        }

        // ---------------------------------------------------------------- sin, cos

        private static double KernelSin(double x, double y, bool hasTail)
        {
            double z = x * x;
            double v = z * x;
            double r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
            return !hasTail ? x + v * (S1 + z * r) : x - ((z * (0.5 * y - v * r) - y) - v * S1);
        }

        private static double KernelCos(double x, double y)
        {
            double z = x * x;
            double r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
            double hz = 0.5 * z;
            double w = 1.0 - hz;
            return w + (((1.0 - w) - hz) + (z * r - x * y));
        }

        /// <summary>x = n pi/2 + (y0 + y1), |y0 + y1| &lt;= pi/4 (about), for finite |x| &gt; pi/4; returns n.</summary>
        private static int Reduce(double x, out double y0, out double y1)
        {
            double ax = Math.Abs(x);
            int n;
            if (ax < MediumReduction)
            {
                // fdlibm's medium case: pi/2 in three 33-bit pieces, a piece more while the difference cancels.
                double fn = Math.Floor(ax * InvPio2 + 0.5);
                n = (int)fn;
                double r = ax - fn * Pio2_1;
                double w = fn * Pio2_1t;
                y0 = r - w;
                int j = Exponent(ax);
                if (j - Exponent(y0) > 16)
                {
                    double t = r;
                    w = fn * Pio2_2;
                    r = t - w;
                    w = fn * Pio2_2t - ((t - r) - w);
                    y0 = r - w;
                    if (j - Exponent(y0) > 49)
                    {
                        t = r;
                        w = fn * Pio2_3;
                        r = t - w;
                        w = fn * Pio2_3t - ((t - r) - w);
                        y0 = r - w;
                    }
                }

                y1 = (r - y0) - w;
            }
            else
            {
                n = ReduceLarge(ax, out y0, out y1);
            }

            if (x < 0)
            {
                y0 = -y0;
                y1 = -y1;
                return -n;
            }

            return n;
        }

        /// <summary>Payne-Hanek: ax (2/pi) mod 4 from a 192-bit window of 2/pi, in integer arithmetic.</summary>
        private static int ReduceLarge(double ax, out double y0, out double y1)
        {
            long bits = BitConverter.DoubleToInt64Bits(ax);
            int e = (int)((bits >> 52) & 0x7FF) - 1075;                 // ax = m 2^e, e >= -32 here
            ulong m = ((ulong)bits & 0x000FFFFFFFFFFFFFUL) | 0x0010000000000000UL;
            const int Bits = 64 * 20;
            int low = Bits - e - 190;                                     // ax 2/pi mod 4 = (m W mod 2^192) 2^-190
            ulong w0 = TwoOverPiBits(low), w1 = TwoOverPiBits(low + 64), w2 = TwoOverPiBits(low + 128);

            ulong h0 = MultiplyHigh(m, w0, out ulong r0);
            ulong h1 = MultiplyHigh(m, w1, out ulong l1);
            ulong l2 = m * w2;
            ulong r1 = h0 + l1;
            ulong r2 = h1 + l2 + (r1 < h0 ? 1UL : 0UL);

            int n = (int)(r2 >> 62);
            r2 &= 0x3FFFFFFFFFFFFFFFUL;                                   // the fraction, 190 bits
            bool negative = (r2 >> 61) != 0;                              // fraction >= 1/2: round n up, fraction - 1
            if (negative)
            {
                n++;
                // 2^190 - fraction, in three words
                r0 = ~r0 + 1;
                r1 = ~r1 + (r0 == 0 ? 1UL : 0UL);
                r2 = (~r2 + (r0 == 0 && r1 == 0 ? 1UL : 0UL)) & 0x3FFFFFFFFFFFFFFFUL;
            }

            // Normalise the 192-bit fraction so its top bit is bit 191, then take 53 + 53 bits.
            int shift = 0;
            while (r2 == 0)
            {
                r2 = r1;
                r1 = r0;
                r0 = 0;
                shift += 64;
            }

            while ((r2 & 0x8000000000000000UL) == 0)
            {
                r2 = (r2 << 1) | (r1 >> 63);
                r1 = (r1 << 1) | (r0 >> 63);
                r0 <<= 1;
                shift++;
            }

            double fHi = (double)(long)(r2 >> 11) * PowerOfTwo(-51 - shift);
            double fLo = (double)(long)(((r2 & 0x7FFUL) << 42) | (r1 >> 22)) * PowerOfTwo(-104 - shift);

            // (fHi + fLo) pi/2 in double-double.
            TwoProduct(fHi, Pio2Hi, out double p, out double pe);
            pe += fHi * Pio2Lo + fLo * Pio2Hi;
            FastTwoSum(p, pe, out y0, out y1);
            if (negative)
            {
                y0 = -y0;
                y1 = -y1;
            }

            return n & 3;
        }

        /// <summary>Bits j .. j+63 of 2^1280 (2/pi) (bit j lowest), zero beyond the table.</summary>
        private static ulong TwoOverPiBits(int j)
        {
            int top = 64 * 20 - 1 - j - 63;                               // position, from the table's first bit, of the chunk's top bit
            int word = top >= 0 ? top / 64 : -((-top + 63) / 64);
            int offset = top - 64 * word;
            ulong first = Word(word) << offset;
            return offset == 0 ? first : first | (Word(word + 1) >> (64 - offset));
        }

        private static ulong Word(int i) => i >= 0 && i < TwoOverPi.Length ? TwoOverPi[i] : 0UL;

        /// <summary>The high 64 bits of a * b (the low ones in <paramref name="low"/>).</summary>
        private static ulong MultiplyHigh(ulong a, ulong b, out ulong low)
        {
            ulong aLo = a & 0xFFFFFFFFUL, aHi = a >> 32, bLo = b & 0xFFFFFFFFUL, bHi = b >> 32;
            ulong ll = aLo * bLo, lh = aLo * bHi, hl = aHi * bLo, hh = aHi * bHi;
            ulong middle = (ll >> 32) + (lh & 0xFFFFFFFFUL) + (hl & 0xFFFFFFFFUL);
            low = (middle << 32) | (ll & 0xFFFFFFFFUL);
            return hh + (lh >> 32) + (hl >> 32) + (middle >> 32);
        }
    }
}
