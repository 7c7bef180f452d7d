using System;
using System.Collections.Generic;
using System.Linq;
using MagnusBall.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// The <c>golf</c> preset against TrackMan: the 24-shot session it was calibrated on (once, all shots at
    /// once) and the tour averages it was not (data/published/trackman-tour-averages.json). docs/validation.md
    /// prints these tables.
    /// </summary>
    [TestFixture]
    [Category("Validation")]
    public class GolfValidationTests
    {
        internal static List<(GolfShot Shot, GolfResult Result)> FlyAll(SportPreset preset, IEnumerable<GolfShot> shots) =>
            shots.Select(s => (s, GolfFlights.Fly(preset, s, GolfFlights.TrackManAir))).ToList();

        private static double CarryError(GolfShot s, GolfResult r) => (r.Carry - s.Carry) / s.Carry * 100;

        private static void Print(string title, List<(GolfShot Shot, GolfResult Result)> flights)
        {
            TestContext.Out.WriteLine(title);
            TestContext.Out.WriteLine("| shot | carry measured | carry simulated | error | apex measured | apex simulated | landing measured | landing simulated |");
            TestContext.Out.WriteLine("|---|---|---|---|---|---|---|---|");
            foreach ((GolfShot s, GolfResult r) in flights)
            {
                TestContext.Out.WriteLine(
                    $"| {s.Name} | {s.Carry / GolfFlights.Yard:F1} yd | {r.Carry / GolfFlights.Yard:F1} yd | {CarryError(s, r):+0.0;-0.0} % | " +
                    $"{(s.Apex.HasValue ? (s.Apex.Value / GolfFlights.Yard).ToString("F1") + " yd" : "-")} | {r.Apex / GolfFlights.Yard:F1} yd | " +
                    $"{(s.LandAngle.HasValue ? s.LandAngle.Value.ToString("F1") + " deg" : "-")} | {r.LandAngle:F1} deg |");
            }
        }

        private static (double Median, double Worst, double LandMedian, double LandSigned) Summary(List<(GolfShot Shot, GolfResult Result)> flights)
        {
            double median = GolfFlights.Median(flights.Select(f => Math.Abs(CarryError(f.Shot, f.Result))));
            double worst = flights.Max(f => Math.Abs(CarryError(f.Shot, f.Result)));
            var landed = flights.Where(f => f.Shot.LandAngle.HasValue).ToList();
            double land = GolfFlights.Median(landed.Select(f => Math.Abs(f.Result.LandAngle - f.Shot.LandAngle!.Value)));
            double signed = GolfFlights.Median(landed.Select(f => f.Result.LandAngle - f.Shot.LandAngle!.Value));
            return (median, worst, land, signed);
        }

        /// <summary>The golf preset with <see cref="MagnusBall.Aerodynamics.GolfNaruoUsgaLaw"/> for drag and lift.</summary>
        internal static SportPreset NaruoUsga() =>
            SportPresets.Golf.WithDrag(MagnusBall.Aerodynamics.GolfNaruoUsgaLaw.Instance).WithLift(MagnusBall.Aerodynamics.GolfNaruoUsgaLaw.Instance);

        /// <summary>Median |apex error| in % over the shots with a measured apex.</summary>
        internal static double ApexMedian(List<(GolfShot Shot, GolfResult Result)> flights) =>
            GolfFlights.Median(flights.Where(f => f.Shot.Apex.HasValue).Select(f => Math.Abs(f.Result.Apex - f.Shot.Apex!.Value) / f.Shot.Apex!.Value * 100));

        [Test]
        public void Calibration_TheSessionItWasFittedTo()
        {
            var flights = FlyAll(SportPresets.Golf, GolfFlights.Session());
            Print("TrackMan session (calibration set, 24 shots)", flights);
            var s = Summary(flights);
            TestContext.Out.WriteLine($"carry |error| median {s.Median:F2} %, worst {s.Worst:F2} %; landing |error| median {s.LandMedian:F2} deg (signed {s.LandSigned:+0.00;-0.00})");

            // The calibration's own documented result (docs/presets.md: carry median 3.46 %, landing median 0.73 deg,
            // with the power-law lift of issue 12's second pass; 3.4 % and 0.4 deg with the saturating lift before it):
            // a regression bound, not a validation; a change to the law or its constant that fits the session
            // worse than that, by more than the constant's rounding (0.05 % and 0.05 deg), fails here.
            Assert.That(s.Median, Is.LessThan(3.51));
            Assert.That(s.LandMedian, Is.LessThan(0.78));
        }

        [Test]
        public void Validation_TourAveragesOutsideTheCalibration()
        {
            var flights = FlyAll(SportPresets.Golf, GolfFlights.TourAverages());
            Print("TrackMan tour averages (not used in the calibration)", flights);
            var s = Summary(flights);
            TestContext.Out.WriteLine($"carry |error| median {s.Median:F2} %, worst {s.Worst:F2} %; landing |error| median {s.LandMedian:F2} deg (signed {s.LandSigned:+0.00;-0.00})");

            // Issue 43's targets: carry median <= 1.5 %, worst <= 5 %, landing-angle median within 1.5 deg (issue 12's, met
            // and asserted before: median <= 2.5 %, worst <= 8 %). A missed target is printed with its number
            // (docs/validation.md states which are met), not hidden by a wider bound.
            TestContext.Out.WriteLine($"apex |error| median {ApexMedian(flights):F1} %");
            TestContext.Out.WriteLine($"target carry median <= 1.5 %: {(s.Median <= 1.5 ? "met" : "MISSED")}; worst <= 5 %: {(s.Worst <= 5 ? "met" : "MISSED")}; landing median <= 1.5 deg: {(s.LandMedian <= 1.5 ? "met" : "MISSED")}");
            Assert.That(s.Median, Is.LessThanOrEqualTo(2.5), "issue 12's target, met since");
            Assert.That(s.Worst, Is.LessThanOrEqualTo(8), "issue 12's target, met since");

            // For comparison (docs/validation.md): the other golf presets on the same tour averages.
            foreach (SportPreset other in new[] { SportPresets.GolfBearmanHarvey, SportPresets.GolfLinear2023, SportPresets.GolfSmitsSmith })
            {
                var o = Summary(FlyAll(other, GolfFlights.TourAverages()));
                var c = Summary(FlyAll(other, GolfFlights.Session()));
                TestContext.Out.WriteLine($"{other.Name}: tour carry median {o.Median:F2} %, worst {o.Worst:F2} %, landing median {o.LandMedian:F2} deg; session carry median {c.Median:F2} %, worst {c.Worst:F2} %, landing median {c.LandMedian:F2} deg");
            }

            // The law from measured coefficients only (GolfNaruoUsgaLaw: Naruo et al. 2004 in S, the USGA model's Re terms;
            // nothing fitted to a flight), flown with the golf ball and spin decay. docs/validation.md states these numbers;
            // the asserts are regression bounds at them plus their last printed digit.
            SportPreset measured = NaruoUsga();
            Print("The same tour averages with GolfNaruoUsgaLaw (measured coefficients only)", FlyAll(measured, GolfFlights.TourAverages()));
            Print("The calibration session with GolfNaruoUsgaLaw (not fitted to it)", FlyAll(measured, GolfFlights.Session()));
            var mt = Summary(FlyAll(measured, GolfFlights.TourAverages()));
            var ms = Summary(FlyAll(measured, GolfFlights.Session()));
            TestContext.Out.WriteLine($"GolfNaruoUsgaLaw (measured coefficients, not a preset): tour carry median {mt.Median:F2} %, worst {mt.Worst:F2} %, landing median {mt.LandMedian:F2} deg (signed {mt.LandSigned:+0.00;-0.00}), apex median {ApexMedian(FlyAll(measured, GolfFlights.TourAverages())):F1} %; session carry median {ms.Median:F2} %, worst {ms.Worst:F2} %, landing median {ms.LandMedian:F2} deg, apex median {ApexMedian(FlyAll(measured, GolfFlights.Session())):F1} %");
            Assert.That(mt.Median, Is.LessThan(2.72));
            Assert.That(mt.LandMedian, Is.LessThan(3.85));
            Assert.That(ms.Median, Is.LessThan(1.37));

            // For docs/validation.md: a modern ball's trajectory-fitted law (Ferguson, McNally & McPhee 2022), flown
            // through the same harness; not a preset, printed only.
            SportPreset ferguson = SportPresets.Golf.WithDrag(FergusonQuadratic.Instance).WithLift(FergusonQuadratic.Instance);
            var ft = Summary(FlyAll(ferguson, GolfFlights.TourAverages()));
            var fs = Summary(FlyAll(ferguson, GolfFlights.Session()));
            TestContext.Out.WriteLine($"Ferguson et al. 2022 quadratics (test-local): tour carry median {ft.Median:F2} %, worst {ft.Worst:F2} %, landing median {ft.LandMedian:F2} deg (signed {ft.LandSigned:+0.00;-0.00}); session carry median {fs.Median:F2} %, worst {fs.Worst:F2} %, landing median {fs.LandMedian:F2} deg");

            // Hard floor, so a broken law cannot pass silently: every tour shot within 15 % of its carry (twice the
            // 8 % target; the uncalibrated wind-tunnel law misses drivers by up to 20 %).
            Assert.That(s.Worst, Is.LessThan(15));
        }

        /// <summary>
        /// Ferguson, McNally &amp; McPhee (2022), "Predicting the flight of a golf ball: comparing a physics-based aerodynamic
        /// model to a neural network", ISEA 2022 (Engineering of Sport 14), doi 10.5703/1288284317493: C_D = 0.1304 +
        /// 0.9287 S - 0.8259 S^2 and C_L = 0.0504 + 1.2031 S - 1.1490 S^2, fitted to the radar-measured carry and apex of
        /// 1040 shots of a 2021 Titleist Pro V1 (S 0.02-0.75). Constants as quoted by public code (open-flight/openflight,
        /// src/openflight/ballistics.py, commit 6f482c87e9d33789cc7d82c25e32856dfea2e65a; the same six in a second
        /// public copy), the paper itself not read here; S held at 0.75 beyond the fit and C_L kept &gt;= 0, as there.
        /// Spin decay stays the golf preset's 4 %/s.
        /// </summary>
        private sealed class FergusonQuadratic : MagnusBall.Aerodynamics.IDragModel, MagnusBall.Aerodynamics.ILiftModel
        {
            public static readonly FergusonQuadratic Instance = new FergusonQuadratic();

            private static double Clamp(double s) => s > 0.75 ? 0.75 : s > 0 ? s : 0;

            public double DragCoefficient(in MagnusBall.Aerodynamics.AeroConditions conditions)
            {
                double s = Clamp(conditions.SpinParameter);
                return 0.1304 + 0.9287 * s - 0.8259 * s * s;
            }

            public double LiftCoefficient(in MagnusBall.Aerodynamics.AeroConditions conditions)
            {
                if (!(conditions.TransverseSpinParameter > 0))
                {
                    return 0;
                }

                double s = Clamp(conditions.TransverseSpinParameter);
                return Math.Max(0, 0.0504 + 1.2031 * s - 1.1490 * s * s);
            }
        }

        private sealed class ScaledDrag : MagnusBall.Aerodynamics.IDragModel
        {
            private readonly MagnusBall.Aerodynamics.IDragModel _law;
            private readonly double _k;

            public ScaledDrag(MagnusBall.Aerodynamics.IDragModel law, double k)
            {
                _law = law;
                _k = k;
            }

            public double DragCoefficient(in MagnusBall.Aerodynamics.AeroConditions conditions) => _k * _law.DragCoefficient(conditions);
        }

        private sealed class ScaledLift : MagnusBall.Aerodynamics.ILiftModel
        {
            private readonly MagnusBall.Aerodynamics.ILiftModel _law;
            private readonly double _k;

            public ScaledLift(MagnusBall.Aerodynamics.ILiftModel law, double k)
            {
                _law = law;
                _k = k;
            }

            public double LiftCoefficient(in MagnusBall.Aerodynamics.AeroConditions conditions) => _k * _law.LiftCoefficient(conditions);
        }

        /// <summary>
        /// Why the landing-angle target is missed (docs/validation.md): the tour chart's long irons land 46-48 deg
        /// from apexes of only 27-28 yd. More drag with the wind-tunnel lift does not get there: the golf law's C_D
        /// scaled by 1-1.45 (drag rising more steeply with spin, as the issue suggests, is inside that range for these
        /// spin parameters) lands the PGA 4-iron (137 mph, 11 deg, 4836 rpm: 203 yd, apex 28 yd, 48 deg) at most 1.1
        /// deg steeper and never within 2 deg; a faster spin decay makes it flatter; only about 20 % more lift does,
        /// and that raises the apex by about 5 yd. The law from the descent's measured coefficients
        /// (<see cref="MagnusBall.Aerodynamics.GolfNaruoUsgaLaw"/>) lands it at 41.2 deg.
        /// </summary>
        [Test]
        public void TourLongIron_MoreDragAloneDoesNotSteepenTheLanding()
        {
            GolfShot iron = GolfFlights.TourAverages().Single(t => t.Name == "PGA 4-iron");
            GolfResult Fly(double kLift, double kDrag)
            {
                SportPreset scaled = SportPresets.Golf.WithLift(new ScaledLift(SportPresets.Golf.Lift!, kLift)).WithDrag(new ScaledDrag(SportPresets.Golf.Drag!, kDrag));
                GolfResult r = GolfFlights.Fly(scaled, iron, GolfFlights.TrackManAir);
                TestContext.Out.WriteLine($"C_L x {kLift}, C_D x {kDrag}: carry {r.Carry / GolfFlights.Yard:F1} yd, apex {r.Apex / GolfFlights.Yard:F1} yd, landing {r.LandAngle:F1} deg (chart: 203 yd, 28 yd, 48 deg)");
                return r;
            }

            double measured = iron.LandAngle!.Value;
            foreach (double kDrag in new[] { 1.0, 1.15, 1.3, 1.45 })
            {
                // 2 deg: the issue's landing-angle target.
                Assert.That(measured - Fly(1.0, kDrag).LandAngle, Is.GreaterThan(2), $"C_D x {kDrag} alone reached the chart's landing angle");
            }

            // Faster spin decay (twice TrackMan's 4 %/s) leaves less lift for the descent: the landing gets flatter, not steeper.
            GolfResult unscaled = GolfFlights.Fly(SportPresets.Golf, iron, GolfFlights.TrackManAir);
            GolfResult fastDecay = GolfFlights.Fly(SportPresets.Golf.WithSpinDecay(new MagnusBall.Aerodynamics.ExponentialSpinDecay(SportPresets.GolfSpinDecayTimeConstant / 2)), iron, GolfFlights.TrackManAir);
            TestContext.Out.WriteLine($"spin decay 8 %/s instead of 4 %/s: carry {fastDecay.Carry / GolfFlights.Yard:F1} yd, apex {fastDecay.Apex / GolfFlights.Yard:F1} yd, landing {fastDecay.LandAngle:F1} deg");
            Assert.That(fastDecay.LandAngle, Is.LessThan(unscaled.LandAngle));

            // The descent's measured coefficients (GolfNaruoUsgaLaw: C_D 0.33 at S 0.3, 0.41 at S 0.5) do not reach it either.
            GolfResult naruo = GolfFlights.Fly(NaruoUsga(), iron, GolfFlights.TrackManAir);
            TestContext.Out.WriteLine($"GolfNaruoUsgaLaw: carry {naruo.Carry / GolfFlights.Yard:F1} yd, apex {naruo.Apex / GolfFlights.Yard:F1} yd, landing {naruo.LandAngle:F1} deg");
            Assert.That(measured - naruo.LandAngle, Is.GreaterThan(2), "the measured descent coefficients reached the chart's landing angle");

            GolfResult moreLift = Fly(1.2, 1.15);
            Assert.That(measured - moreLift.LandAngle, Is.LessThan(2), "20 % more lift (with 15 % more drag) reaches it");
            Assert.That(moreLift.Apex - iron.Apex!.Value, Is.GreaterThan(4 * GolfFlights.Yard), "at the cost of the apex");
        }
    }
}
