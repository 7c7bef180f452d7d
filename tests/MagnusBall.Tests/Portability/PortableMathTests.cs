using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace MagnusBall.Tests.Portability
{
    /// <summary>
    /// PortableMath against System.Math over each function's whole input range: seeded random bit patterns (every
    /// exponent, subnormals included), uniform samples where the library calls them, the hard cases of argument
    /// reduction, and the special values. The bound asserted is the one PortableMath's docs state (1 ulp); the
    /// reference is Math on the runtime running the test (glibc on Linux CoreCLR, correctly rounded in almost all
    /// cases, so a 1-ulp bound means PortableMath is faithfully rounded). The worst cases measured are printed.
    /// </summary>
    public class PortableMathTests
    {
        private const long Bound = 1; // ulp: PortableMath's documented accuracy (docs/determinism.md)
        private const int Samples = 200_000;

        [Test]
        public void Exp_IsWithinOneUlp_OverItsRange()
        {
            var random = new Random(1501);
            var inputs = new List<double> { 0, -0.0, 1, -1, 1e-300, -1e-300, 709.78, 709.782712893384, -745.13, -745.1332191019411, -708.4, -709.5, 0.5 * Math.Log(2), 1e-9 };
            for (int i = 0; i < Samples; i++)
            {
                inputs.Add(-745.2 + 1455.0 * random.NextDouble());
                inputs.Add(-1 + 2 * random.NextDouble());
                double bits = RandomBits(random);
                inputs.Add(Math.Abs(bits) < 710 ? bits : bits * 1e-300);
            }

            AssertWithin(inputs, PortableMath.Exp, Math.Exp, "Exp");
        }

        [Test]
        public void Log_IsWithinOneUlp_OverItsRange()
        {
            var random = new Random(1502);
            var inputs = new List<double> { 1, 2, 0.5, Math.E, 1e-310, double.Epsilon, double.MaxValue, 1 + 1e-15, 1 - 1e-16, Math.Sqrt(2), Math.Sqrt(0.5) };
            for (int i = 0; i < Samples; i++)
            {
                inputs.Add(Math.Abs(RandomBits(random)));
                inputs.Add(0.5 + 1.5 * random.NextDouble());
                inputs.Add(1 + (random.NextDouble() - 0.5) * 1e-6);
            }

            AssertWithin(inputs, PortableMath.Log, Math.Log, "Log");
        }

        [Test]
        public void Pow_IsWithinOneUlp_OverItsRange()
        {
            var random = new Random(1503);
            var pairs = new List<(double, double)>();
            // The exponents the library uses (Stepanek -0.4, Goff-Carre 0.3056, DP54 step control -0.2 and 0.2,
            // the barometric 5.2559, a bounce law's k - 1) on the inputs it feeds them.
            foreach (double y in new[] { -0.4, 0.3056, -0.2, 0.2, 5.25588, 0.5, 1.5, 2, 3, -1, -2 })
            {
                for (int i = 0; i < Samples / 10; i++)
                {
                    pairs.Add((1e-3 + 100 * random.NextDouble(), y));
                }
            }

            for (int i = 0; i < Samples; i++)
            {
                // x anywhere; y such that x^y is finite and not far below the subnormals: |y ln x| spans all of exp's range.
                double x = Math.Abs(RandomBits(random));
                double lnx = Math.Log(x);
                if (lnx != 0)
                {
                    pairs.Add((x, (-745 + 1454 * random.NextDouble()) / lnx));
                }

                pairs.Add((0.5 + random.NextDouble(), -2000 + 4000 * random.NextDouble())); // near 1: a large y
                pairs.Add((-(1 + 9 * random.NextDouble()), Math.Floor(-300 + 600 * random.NextDouble()))); // x < 0, integer y
                pairs.Add((random.NextDouble() * 40, random.NextDouble() * 3 - 1.5));
            }

            Func<double, double, double> reference = Math.Pow; // through a delegate, as everywhere here (see SpecialValues)
            long worst = 0;
            (double, double) worstAt = default;
            foreach ((double x, double y) in pairs)
            {
                long ulps = Ulps(PortableMath.Pow(x, y), reference(x, y));
                if (ulps > worst)
                {
                    worst = ulps;
                    worstAt = (x, y);
                }
            }

            TestContext.Out.WriteLine($"Pow: worst {worst} ulp over {pairs.Count} pairs, at ({worstAt.Item1:R}, {worstAt.Item2:R})");
            Assert.That(worst, Is.LessThanOrEqualTo(Bound), $"at x = {worstAt.Item1:R}, y = {worstAt.Item2:R}");
        }

        [Test]
        public void Sin_AndCos_AreWithinOneUlp_OverTheirRange()
        {
            var random = new Random(1504);
            var inputs = new List<double>
            {
                0, -0.0, 1e-300, Math.PI, Math.PI / 2, Math.PI / 4, 1e22, 1e300, double.MaxValue, -double.MaxValue,
                1647099.3291652855, 1647099.3291652858, 7.450580596923828e-09,
            };
            for (int i = 0; i < Samples; i++)
            {
                inputs.Add(-10 + 20 * random.NextDouble());
                inputs.Add(-2e6 + 4e6 * random.NextDouble());
                inputs.Add(RandomBits(random));
                // next to a multiple of pi/2, where the reduction cancels most
                long k = random.Next(1, 2_000_000);
                inputs.Add(BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(k * (Math.PI / 2)) + random.Next(-2, 3)));
            }

            AssertWithin(inputs, PortableMath.Sin, Math.Sin, "Sin");
            AssertWithin(inputs, PortableMath.Cos, Math.Cos, "Cos");
        }

        [TestCase(5.319372648326541e+255, 1.0, -4.687165924254628e-19)] // 6381956970095103 * 2^797, the double nearest a multiple of pi/2 (Kahan & McDonald): Math.Cos is 8 ulp off here
        [TestCase(1e22, -0.8522008497671888, 0.523214785395139)]
        [TestCase(1e300, -0.8178819121159085, -0.5753861119575491)]
        [TestCase(1.7976931348623157e308, 0.004961954789184062, -0.9999876894265599)]
        [TestCase(1647099.3291652855, -6.420676210313675e-11, 1.0)] // 2^20 pi/2 rounded: the medium reduction's end
        public void HardReductions_AreCorrectlyRounded(double x, double sin, double cos)
        {
            // Expected: sin and cos of the double x to 4,000 bits (mpmath), rounded to double
            // (tools/portable-math-constants.py prints them).
            Assert.That(PortableMath.Sin(x), Is.EqualTo(sin));
            Assert.That(PortableMath.Cos(x), Is.EqualTo(cos));
            Assert.That(PortableMath.Sin(-x), Is.EqualTo(-sin));
            Assert.That(PortableMath.Cos(-x), Is.EqualTo(cos));
        }

        [Test]
        public void Atan_IsWithinOneUlp_OverItsRange()
        {
            // Atan is reached directly (Atan2 of x > 0 calls Atan(y / x)), so it is checked on its own over every double:
            // random bit patterns (every exponent and sign, subnormals included), [-10, 10], and fdlibm's reduction
            // breakpoints 7/16, 11/16, 19/16, 39/16 and the 2^66 saturation, where its argument reduction switches.
            var random = new Random(1506);
            var inputs = new List<double> { 0, -0.0, 1, -1, double.Epsilon, double.MaxValue, -double.MaxValue, 1e-300, 7.0 / 16, 11.0 / 16, 19.0 / 16, 39.0 / 16, Math.Pow(2, 66), -Math.Pow(2, 66), Math.Pow(2, -27) };
            foreach (double b in new[] { 7.0 / 16, 11.0 / 16, 19.0 / 16, 39.0 / 16, Math.Pow(2, 66), Math.Pow(2, -27) })
            {
                // The neighbours by bits (not Math.BitIncrement, which Mono 6.8's corlib lacks).
                inputs.Add(BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(b) - 1));
                inputs.Add(BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(b) + 1));
            }

            for (int i = 0; i < Samples; i++)
            {
                inputs.Add(RandomBits(random));
                inputs.Add(-10 + 20 * random.NextDouble());
                inputs.Add((random.NextDouble() - 0.5) * 6);
            }

            AssertWithin(inputs, PortableMath.Atan, Math.Atan, "Atan");
        }

        [Test]
        public void Atan2_IsWithinOneUlp_OverItsRange()
        {
            var random = new Random(1505);
            Func<double, double, double> reference = Math.Atan2;
            long worst = 0;
            (double, double) worstAt = default;
            for (int i = 0; i < 4 * Samples; i++)
            {
                double y, x;
                switch (i % 4)
                {
                    case 0: y = RandomBits(random); x = RandomBits(random); break;
                    case 1: y = -50 + 100 * random.NextDouble(); x = -50 + 100 * random.NextDouble(); break;
                    case 2: y = -1 + 2 * random.NextDouble(); x = Math.Abs(-1 + 2 * random.NextDouble()) + 1e-3; break; // CrossBounce: (vn, tangential speed)
                    default: y = RandomBits(random); x = y * (0.5 + random.NextDouble()); break;
                }

                long ulps = Ulps(PortableMath.Atan2(y, x), reference(y, x));
                if (ulps > worst)
                {
                    worst = ulps;
                    worstAt = (y, x);
                }
            }

            TestContext.Out.WriteLine($"Atan2: worst {worst} ulp, at ({worstAt.Item1:R}, {worstAt.Item2:R})");
            Assert.That(worst, Is.LessThanOrEqualTo(Bound), $"at y = {worstAt.Item1:R}, x = {worstAt.Item2:R}");
        }

        [Test]
        public void SpecialValues_AreMathsBitForBit()
        {
            double[] specials =
            {
                0, -0.0, 1, -1, 0.5, -0.5, 2, -2, 3, -3, 0.4, -0.4, 1e-310, -1e-310, 1e300, -1e300, double.MaxValue, -double.MaxValue,
                double.Epsilon, double.PositiveInfinity, double.NegativeInfinity, double.NaN, Math.PI, -Math.PI, 9007199254740993.0, 1e17 + 1,
            };
            // The references are called through delegates, as in the sweeps: Mono's JIT compiles a direct Math.Sin or
            // Math.Cos call to x87 fsin/fcos, which are wrong far from 0 (fsin(pi) = 1.2246063538223773e-16, fsin(1e300)
            // = 1e300), while a delegate reaches the C library's sin and cos.
            Func<double, double> exp = Math.Exp, log = Math.Log, sin = Math.Sin, cos = Math.Cos;
            Func<double, double, double> pow = Math.Pow, atan2 = Math.Atan2;
            var failures = new List<string>();
            foreach (double a in specials)
            {
                Check("Exp", a, double.NaN, PortableMath.Exp(a), exp(a), failures, exactOnly: !double.IsFinite(a) || a == 0);
                Check("Log", a, double.NaN, PortableMath.Log(a), log(a), failures, exactOnly: !(a > 0) || double.IsInfinity(a) || a == 1);
                Check("Sin", a, double.NaN, PortableMath.Sin(a), sin(a), failures, exactOnly: !double.IsFinite(a) || a == 0);
                Check("Cos", a, double.NaN, PortableMath.Cos(a), cos(a), failures, exactOnly: !double.IsFinite(a) || a == 0);
                foreach (double b in specials)
                {
                    bool special = !double.IsFinite(a) || !double.IsFinite(b) || a == 0 || b == 0;
                    Check("Pow", a, b, PortableMath.Pow(a, b), pow(a, b), failures, exactOnly: special || a == 1 || a == -1);
                    Check("Atan2", a, b, PortableMath.Atan2(a, b), atan2(a, b), failures, exactOnly: special);
                }
            }

            Assert.That(failures, Is.Empty, string.Join("\n", failures));
        }

        /// <summary>
        /// The same bits on every runtime: a hash of 60,000 results per function over the whole range, recorded on
        /// CoreCLR (.NET 10, x64 Linux). tools/test-mono.sh runs this under Mono with and without its intrinsics.
        /// </summary>
        [Test]
        public void Results_AreTheRecordedBits()
        {
            var random = new Random(1506);
            ulong hash = 14695981039346656037UL; // FNV-1a over the result bits
            void Add(double v)
            {
                ulong bits = (ulong)BitConverter.DoubleToInt64Bits(v);
                for (int b = 0; b < 64; b += 8)
                {
                    hash = (hash ^ ((bits >> b) & 0xFF)) * 1099511628211UL;
                }
            }

            for (int i = 0; i < 60_000; i++)
            {
                double any = RandomBits(random), small = -20 + 40 * random.NextDouble(), positive = Math.Abs(RandomBits(random));
                Add(PortableMath.Sin(any));
                Add(PortableMath.Cos(small));
                Add(PortableMath.Exp(small * 30));
                Add(PortableMath.Log(positive));
                Add(PortableMath.Pow(positive * 1e-300 + small * small, small * 0.1));
                Add(PortableMath.Atan2(small, any));
            }

            TestContext.Out.WriteLine($"hash 0x{hash:X16}");
            Assert.That(hash, Is.EqualTo(RecordedHash), $"got 0x{hash:X16}");
        }

        private const ulong RecordedHash = 0xD3CD4591547B5EC1UL;

        private static void Check(string name, double a, double b, double actual, double expected, List<string> failures, bool exactOnly)
        {
            long ulps = Ulps(actual, expected);
            bool sameBits = BitConverter.DoubleToInt64Bits(actual) == BitConverter.DoubleToInt64Bits(expected) || (double.IsNaN(actual) && double.IsNaN(expected));
            if (exactOnly ? !sameBits : ulps > Bound)
            {
                failures.Add($"{name}({a:R}, {b:R}) = {actual:R}, Math: {expected:R}");
            }
        }

        private static void AssertWithin(List<double> inputs, Func<double, double> portable, Func<double, double> reference, string name)
        {
            long worst = 0;
            double worstAt = 0;
            foreach (double x in inputs)
            {
                long ulps = Ulps(portable(x), reference(x));
                if (ulps > worst)
                {
                    worst = ulps;
                    worstAt = x;
                }
            }

            TestContext.Out.WriteLine($"{name}: worst {worst} ulp over {inputs.Count} inputs, at {worstAt:R}");
            Assert.That(worst, Is.LessThanOrEqualTo(Bound), $"{name} at x = {worstAt:R}");
        }

        /// <summary>A double with uniformly random bits (any sign, any exponent), finite.</summary>
        private static double RandomBits(Random random)
        {
            while (true)
            {
                long bits = ((long)random.Next() << 33) ^ ((long)random.Next() << 11) ^ random.Next();
                double v = BitConverter.Int64BitsToDouble(bits);
                if (double.IsFinite(v))
                {
                    return v;
                }
            }
        }

        /// <summary>Distance in representable doubles (0 for equal values, +0 and -0 equal; NaN only equals NaN).</summary>
        internal static long Ulps(double a, double b)
        {
            if (double.IsNaN(a) || double.IsNaN(b))
            {
                return double.IsNaN(a) && double.IsNaN(b) ? 0 : long.MaxValue;
            }

            long ia = Ordered(a), ib = Ordered(b);
            return ia > ib ? ia - ib : ib - ia;
        }

        private static long Ordered(double v)
        {
            long bits = BitConverter.DoubleToInt64Bits(v);
            return bits < 0 ? -(bits & long.MaxValue) : bits;
        }
    }
}
