using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using MagnusBall.Aerodynamics;
using NUnit.Framework;

namespace MagnusBall.Tests.Aerodynamics
{
    /// <summary>
    /// <see cref="GolfNaruoUsgaLaw"/> against each source it is built from or checked against
    /// (data/coefficients/naruo-2004-golf-polynomials.csv and golf-descent-points.csv; sources in
    /// data/coefficients/README.md), and its shape: continuous, zero lift without spin, bounded.
    /// </summary>
    [TestFixture]
    public class GolfNaruoUsgaLawTests
    {
        // The spread between balls at one condition in these sources: at Re 7e4 and S 0.18-0.19 Acushnet's Pro V1 and
        // Bridgestone's balls differ by 0.046 in C_D (0.274 against 0.228) and by 0.055 in C_L (0.209 against 0.154).
        // A law for "a modern ball" cannot be closer to every source than the balls are to each other.
        private const double BetweenBallsDrag = 0.046;
        private const double BetweenBallsLift = 0.055;

        private static readonly string[] RecordedDragMisses = { "bearman-harvey-1976-at-21.9mps S 0.11" };

        private static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

        private static double Polynomial(double[] c, double s) => c.Select((k, i) => k * Math.Pow(s, 4 - i)).Sum();

        [Test]
        public void InNaruosRange_ItIsTheirPolynomials()
        {
            var rows = SourceDataTests.ReadCsv("naruo-2004-golf-polynomials.csv");
            double[] cd = rows.Select(r => D(r[1])).ToArray(), cl = rows.Select(r => D(r[2])).ToArray();
            double worstDrag = 0, worstLift = 0;
            for (double s = 0.03; s <= 1.13; s += 0.01)
            {
                foreach (double re in new[] { 7.09e4, 1e5, 1.25e5 })
                {
                    worstDrag = Math.Max(worstDrag, Math.Abs(GolfNaruoUsgaLaw.Drag(s, re) - Polynomial(cd, s)));
                    worstLift = Math.Max(worstLift, Math.Abs(GolfNaruoUsgaLaw.Lift(s, re) - Polynomial(cl, s)));
                }
            }

            TestContext.Out.WriteLine($"largest difference from Naruo et al.'s polynomials over S 0.03-1.13, Re 7.09e4-1.25e5: C_D {worstDrag:F4}, C_L {worstLift:F4}");
            // 0.0075: the USGA Re terms across Naruo's Re range (C_D 0.0165 x 0.25 above Re 1e5, C_L 0.0122 x (1/0.81^2 - 1)
            // = 0.0064 below it); Naruo et al. found no Re dependence that large.
            Assert.That(worstDrag, Is.LessThan(0.0075));
            Assert.That(worstLift, Is.LessThan(0.0075));
        }

        [Test]
        public void EveryMeasuredPoint_IsWithinTheSpreadBetweenBalls()
        {
            var rows = SourceDataTests.ReadCsv("golf-descent-points.csv");
            Assert.That(rows.Count, Is.EqualTo(19));
            double worst = 0;
            var dragMisses = new List<string>();
            foreach (string[] r in rows)
            {
                double s = D(r[3]);
                // Lyu et al. 2018 give no Re per point (balls at 18-91 m/s): the law is checked at every Re of a shot.
                double[] reynolds = r[2].Length > 0 ? new[] { D(r[2]) } : new[] { 5e4, 1e5, 1.5e5, 2e5 };
                foreach (double re in reynolds)
                {
                    // A source's range (low-high) counts as met inside it; the distance is to its nearer end.
                    double Miss(double value, string low, string high) =>
                        low.Length == 0 ? 0 : Math.Max(0, Math.Max(D(low) - value, value - D(high)));
                    double drag = Miss(GolfNaruoUsgaLaw.Drag(s, re), r[4], r[5]);
                    double lift = Miss(GolfNaruoUsgaLaw.Lift(s, re), r[6], r[7]);
                    TestContext.Out.WriteLine($"{r[0]} Re {re:G3} S {s}: C_D {GolfNaruoUsgaLaw.Drag(s, re):F3} (off {drag:F3}), C_L {GolfNaruoUsgaLaw.Lift(s, re):F3} (off {lift:F3})");
                    worst = Math.Max(worst, Math.Max(drag, lift));
                    if (drag > BetweenBallsDrag)
                    {
                        dragMisses.Add($"{r[0]} S {s}");
                    }

                    Assert.That(lift, Is.LessThanOrEqualTo(BetweenBallsLift), $"{r[0]} C_L at Re {re}, S {s}");
                }
            }

            TestContext.Out.WriteLine($"largest distance to a source: {worst:F3}; C_D beyond the spread: {string.Join("; ", dragMisses)}");
            // One recorded miss, not hidden by a wider bound: Bearman & Harvey's C_D at S 0.11 (21.9 m/s), 0.052 above the law.
            Assert.That(dragMisses, Is.EquivalentTo(RecordedDragMisses));
        }

        [Test]
        public void DragRisesSteeplyWithSpin_InTheDescent()
        {
            // The issue's observation of every measured set: C_D 0.33-0.44 at S 0.3-0.5 at descent speeds.
            foreach (double re in new[] { 6e4, 9e4, 1.2e5 })
            {
                Assert.That(GolfNaruoUsgaLaw.Drag(0.3, re), Is.InRange(0.31, 0.35));
                Assert.That(GolfNaruoUsgaLaw.Drag(0.5, re), Is.InRange(0.39, 0.44));
            }
        }

        [Test]
        public void Shape_ContinuousZeroLiftWithoutSpinAndBounded()
        {
            Assert.That(GolfNaruoUsgaLaw.Lift(0, 1e5), Is.EqualTo(0));
            Assert.That(GolfNaruoUsgaLaw.Lift(double.NaN, double.NaN), Is.EqualTo(0));
            // Continuous at the ends of the ranges the law is held at: S 0.03 and 1.13, Re 0.81e5 and 2e5.
            foreach ((double s, double re) in new[] { (0.03, 1e5), (1.13, 1e5), (0.2, 0.81e5), (0.2, 2e5) })
            {
                const double h = 1e-9;
                Assert.That(GolfNaruoUsgaLaw.Drag(s + h, re + h), Is.EqualTo(GolfNaruoUsgaLaw.Drag(s - h, re - h)).Within(1e-6));
                Assert.That(GolfNaruoUsgaLaw.Lift(s + h, re + h), Is.EqualTo(GolfNaruoUsgaLaw.Lift(s - h, re - h)).Within(1e-6));
            }

            foreach (double s in new[] { 0, 1e-6, 0.1, 1, 1.13, 5, double.PositiveInfinity, double.NaN })
            {
                foreach (double re in new[] { 0, 1, 5e4, 1e5, 3e5, 1e9, double.PositiveInfinity, double.NaN })
                {
                    double cd = GolfNaruoUsgaLaw.Drag(s, re), cl = GolfNaruoUsgaLaw.Lift(s, re);
                    Assert.That(cd, Is.InRange(0.20, GolfNaruoUsgaLaw.DragBound), $"C_D at S {s}, Re {re}");
                    Assert.That(cl, Is.InRange(0.0, GolfNaruoUsgaLaw.LiftBound), $"C_L at S {s}, Re {re}");
                }
            }
        }
    }
}
