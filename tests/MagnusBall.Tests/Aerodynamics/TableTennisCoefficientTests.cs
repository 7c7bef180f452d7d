using System;
using System.Linq;
using MagnusBall.Aerodynamics;
using MagnusBall.Presets;
using MagnusBall.Tests.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Aerodynamics
{
    /// <summary>
    /// The table-tennis laws (<see cref="ContiTableTennisDrag"/>, <see cref="ContiTableTennisLift"/>; Conti et al. 2026,
    /// arXiv:2606.28805, second-hand): continuity,
    /// bounds, the lift's valley, and a spinning shot that dips with topspin and floats with backspin. Their agreement with
    /// their source's tables is in SourceDataTests (which reads files, so the Mono suite leaves it out).
    /// </summary>
    [TestFixture]
    public class TableTennisCoefficientTests
    {
        [Test]
        public void BothLaws_AreContinuous_Bounded_AndNeverNaN()
        {
            double largestLiftStep = 0, largestDragStep = 0;
            foreach (double speed in new[] { 0.0, 1e-9, 0.5, 2, 5, 7.5, 11, 13.5, 17, 25, 300 })
            {
                double previousLift = double.NaN, previousDrag = double.NaN;
                for (double w = 0; w <= 3000; w += 0.5)
                {
                    var c = new AeroConditions(speed, w, w, 0.02, 1.225, Air.SeaLevel.DynamicViscosity);
                    double cl = ContiTableTennisLift.Instance.LiftCoefficient(c), cd = ContiTableTennisDrag.Instance.DragCoefficient(c);
                    Assert.That(cl, Is.InRange(0, ContiTableTennisLift.Largest), $"C_L at {speed} m/s, {w} rad/s");
                    Assert.That(cd, Is.InRange(0.37, ContiTableTennisDrag.Largest), $"C_D at {speed} m/s, {w} rad/s");
                    if (speed >= 0.5 && !double.IsNaN(previousLift))
                    {
                        largestLiftStep = Math.Max(largestLiftStep, Math.Abs(cl - previousLift));
                        largestDragStep = Math.Max(largestDragStep, Math.Abs(cd - previousDrag));
                    }

                    previousLift = cl;
                    previousDrag = cd;
                }
            }

            // Continuity: over 0.5 rad/s steps neither coefficient moves by more than a slope's worth (C_L's steepest
            // slope, (8/3) C_M r / s at 0.5 m/s with C_M 0.08, is 0.0085 per rad/s, so 0.005 per step; a jump of the fit's
            // 0.022 in C_M would be (8/3) x 0.022 x S, 0.06 at S 1).
            TestContext.Out.WriteLine($"largest step in 0.5 rad/s: C_L {largestLiftStep:G3}, C_D {largestDragStep:G3}");
            Assert.That(largestLiftStep, Is.LessThan(0.005));
            Assert.That(largestDragStep, Is.LessThan(0.005));

            // S infinite (speed underflowing against the spin), NaN inputs: 0, never NaN.
            Assert.That(ContiTableTennisLift.Evaluate(0.0, 300, double.PositiveInfinity), Is.EqualTo(0));
            Assert.That(ContiTableTennisLift.Evaluate(double.NaN, double.NaN, double.NaN), Is.EqualTo(0));
            Assert.That(ContiTableTennisLift.Evaluate(1.7976931348623157E+308, double.PositiveInfinity, double.PositiveInfinity), Is.EqualTo(0));
            Assert.That(ContiTableTennisDrag.Evaluate(double.NaN, double.NaN), Is.EqualTo(0.55));
            Assert.That(ContiTableTennisDrag.Evaluate(10, double.PositiveInfinity), Is.EqualTo(ContiTableTennisDrag.Evaluate(10, 2)));
        }

        [Test]
        public void Lift_HasTheValleyOfTheLiftCrisis()
        {
            // At 13.5 m/s (one of the source's rows) C_L rises with spin to a peak, falls, and rises again: the valley
            // Miyazaki et al. (2017) measured in flight. Checked for its shape (their numbers were not available here).
            double Cl(double w) => ContiTableTennisLift.Evaluate(13.5, w, 0.02 * w / 13.5);
            double[] w = Enumerable.Range(1, 120).Select(i => 10.0 * i).ToArray();
            double[] cl = w.Select(Cl).ToArray();
            int peak = Array.IndexOf(cl, cl.Take(60).Max());
            double[] after = cl.Skip(peak).Take(60 - peak).ToArray();
            int valley = peak + Array.IndexOf(after, after.Min());
            TestContext.Out.WriteLine($"13.5 m/s: C_L peak {cl[peak]:F3} at S {0.02 * w[peak] / 13.5:F2}, valley {cl[valley]:F3} at S {0.02 * w[valley] / 13.5:F2}, {Cl(1000):F3} at S {0.02 * 1000 / 13.5:F2}");
            Assert.That(cl[valley], Is.LessThan(cl[peak] - 0.03));
            Assert.That(Cl(1000), Is.GreaterThan(cl[valley] + 0.03));
        }

        [Test]
        public void SpinningShot_TopspinDips_BackspinFloats()
        {
            // A 10 m/s drive at 8 deg from 0.25 m above the table, 60 rev/s (S about 0.75 at launch): with topspin the
            // Magnus force points down and the ball lands shorter and flies lower than without spin; with backspin it
            // points up and the ball carries further (Conti et al.'s C_L is positive at every spin, so the signs follow).
            FlightModel model = SportPresets.TableTennis.CreateModel(Air.SeaLevel, Gravity.ZUp);
            var up = Vector3d.UnitZ;
            var downrange = Vector3d.UnitX;
            double w = Spin.FromRevolutionsPerSecond(60);
            ShotOutcome top = ShotFlight.Fly(model, ShotFlight.Launch(up, downrange, 0.25, 10, 8, v => Spin.Topspin(v, up, w)));
            ShotOutcome flat = ShotFlight.Fly(model, ShotFlight.Launch(up, downrange, 0.25, 10, 8, v => Vector3d.Zero));
            ShotOutcome back = ShotFlight.Fly(model, ShotFlight.Launch(up, downrange, 0.25, 10, 8, v => Spin.Backspin(v, up, w)));
            TestContext.Out.WriteLine($"table tennis 10 m/s, 8 deg, 60 rev/s: topspin lands {top.Landing.X:F2} m (apex {top.Apex:F3} m), flat {flat.Landing.X:F2} m (apex {flat.Apex:F3} m), backspin {back.Landing.X:F2} m (apex {back.Apex:F3} m)");
            Assert.That(top.Landing.X, Is.LessThan(flat.Landing.X));
            Assert.That(top.Apex, Is.LessThan(flat.Apex));
            Assert.That(back.Landing.X, Is.GreaterThan(flat.Landing.X));
            Assert.That(back.Apex, Is.GreaterThan(flat.Apex));
        }
    }
}
