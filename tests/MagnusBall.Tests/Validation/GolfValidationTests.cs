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

        [Test]
        public void Calibration_TheSessionItWasFittedTo()
        {
            var flights = FlyAll(SportPresets.Golf, GolfFlights.Session());
            Print("TrackMan session (calibration set, 24 shots)", flights);
            var s = Summary(flights);
            TestContext.Out.WriteLine($"carry |error| median {s.Median:F2} %, worst {s.Worst:F2} %; landing |error| median {s.LandMedian:F2} deg (signed {s.LandSigned:+0.00;-0.00})");

            // The calibration's own documented result (docs/presets.md: carry median 3.6 %, landing median 0.4 deg):
            // a regression bound, not a validation; a change to the law or its constant that fits the session
            // worse than that, by more than the constant's rounding (0.1 %), fails here.
            Assert.That(s.Median, Is.LessThan(3.7));
            Assert.That(s.LandMedian, Is.LessThan(0.5));
        }

        [Test]
        public void Validation_TourAveragesOutsideTheCalibration()
        {
            var flights = FlyAll(SportPresets.Golf, GolfFlights.TourAverages());
            Print("TrackMan tour averages (not used in the calibration)", flights);
            var s = Summary(flights);
            TestContext.Out.WriteLine($"carry |error| median {s.Median:F2} %, worst {s.Worst:F2} %; landing |error| median {s.LandMedian:F2} deg (signed {s.LandSigned:+0.00;-0.00})");

            // Targets from the issue (golf developers expect about 2 %: "launch-monitor-calibrated peers reach
            // that"): median <= 2.5 %, worst <= 8 %, landing angle median within 2 deg. A missed target is printed
            // with its number (docs/validation.md states which are met), not hidden by a wider bound.
            TestContext.Out.WriteLine($"target carry median <= 2.5 %: {(s.Median <= 2.5 ? "met" : "MISSED")}; worst <= 8 %: {(s.Worst <= 8 ? "met" : "MISSED")}; landing median <= 2 deg: {(s.LandMedian <= 2 ? "met" : "MISSED")}");

            // For comparison (docs/validation.md): the other golf presets on the same tour averages.
            foreach (SportPreset other in new[] { SportPresets.GolfBearmanHarvey, SportPresets.GolfLinear2023, SportPresets.GolfSmitsSmith })
            {
                var o = Summary(FlyAll(other, GolfFlights.TourAverages()));
                var c = Summary(FlyAll(other, GolfFlights.Session()));
                TestContext.Out.WriteLine($"{other.Name}: tour carry median {o.Median:F2} %, worst {o.Worst:F2} %, landing median {o.LandMedian:F2} deg; session carry median {c.Median:F2} %, worst {c.Worst:F2} %, landing median {c.LandMedian:F2} deg");
            }

            // Hard floor, so a broken law cannot pass silently: every tour shot within 15 % of its carry (twice the
            // 8 % target; the uncalibrated wind-tunnel law misses drivers by up to 20 %).
            Assert.That(s.Worst, Is.LessThan(15));
        }
    }
}
