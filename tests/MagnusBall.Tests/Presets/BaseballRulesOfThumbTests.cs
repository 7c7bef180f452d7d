using System;
using MagnusBall.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Presets
{
    /// <summary>
    /// Altitude, temperature, pressure and a headwind move a baseball fly ball in the directions and rough sizes
    /// of the rules of thumb for a 400 ft fly ball (docs/references.md section 6): +6 ft per 1000 ft of
    /// altitude, +4 ft per 10 degF, +4 ft per inHg lower pressure, a 10 mph headwind takes 400 ft to about 370 ft.
    /// </summary>
    /// <remarks>
    /// "Rough size" is taken as within a factor of 2 either way of the rule, for every rule alike: the rules
    /// are rounded to whole feet and come without error bars, and the temperature rule also contains the
    /// livelier rebound of a warm ball off the bat (Adair, "The Physics of Baseball"), which no flight model has.
    /// The launch (28 deg, 1800 rpm backspin, from 1 m) is fixed; its speed is solved so the baseline carry is
    /// 400 ft at 70 degF, 101325 Pa, dry air.
    /// </remarks>
    [TestFixture]
    public class BaseballRulesOfThumbTests
    {
        private const double Baseline = 21.1; // 70 degF
        private const double PascalsPerInHg = 3386.39;

        internal static double CarryFeet(Air air, double mph)
        {
            Vector3d up = Vector3d.UnitZ;
            FlightState start = ShotFlight.Launch(up, Vector3d.UnitX, 1.0, mph * ShotFlight.MetresPerSecondPerMph, 28,
                v => Spin.Backspin(v, up, Spin.FromRpm(1800)));
            ShotOutcome outcome = ShotFlight.Fly(SportPresets.Baseball.CreateModel(air, Gravity.ZUp), start);
            return outcome.Landing.X / ShotFlight.MetresPerFoot;
        }

        private static double _speed;

        [OneTimeSetUp]
        public void SolveTheFourHundredFootLaunch()
        {
            Air air = Air.FromWeather(Baseline, Atmosphere.SeaLevelPressure);
            double low = 80, high = 130;
            for (int i = 0; i < 30; i++)
            {
                double mid = 0.5 * (low + high);
                if (CarryFeet(air, mid) < 400) { low = mid; } else { high = mid; }
            }

            _speed = 0.5 * (low + high);
            TestContext.Out.WriteLine($"400 ft launch: {_speed:F2} mph");
        }

        private static void AssertRoughly(double measured, double rule, string what)
        {
            TestContext.Out.WriteLine($"{what}: {measured:+0.0;-0.0} ft (rule of thumb {rule:+0;-0} ft)");
            Assert.That(Math.Sign(measured), Is.EqualTo(Math.Sign(rule)), what);
            // Factor of 2 either way: see the class remarks.
            Assert.That(Math.Abs(measured), Is.InRange(Math.Abs(rule) / 2, Math.Abs(rule) * 2), what);
        }

        [Test]
        public void ThousandFeetOfAltitude_AddsAboutSixFeet()
        {
            double sea = CarryFeet(Air.AtAltitude(0, Baseline), _speed);
            double up = CarryFeet(Air.AtAltitude(1000 * ShotFlight.MetresPerFoot, Baseline), _speed);
            AssertRoughly(up - sea, 6, "+1000 ft altitude");
        }

        [Test]
        public void TenDegreesFahrenheitWarmer_AddsAboutFourFeet()
        {
            double warm = CarryFeet(Air.FromWeather(Baseline + 50.0 / 9.0, Atmosphere.SeaLevelPressure), _speed);
            AssertRoughly(warm - 400, 4, "+10 degF");
        }

        [Test]
        public void OneInchOfMercuryLowerPressure_AddsAboutFourFeet()
        {
            double low = CarryFeet(Air.FromWeather(Baseline, Atmosphere.SeaLevelPressure - PascalsPerInHg), _speed);
            AssertRoughly(low - 400, 4, "-1 inHg");
        }

        [Test]
        public void TenMphHeadwind_TakesFourHundredFeetToAbout370()
        {
            var headwind = new Vector3d(-10 * ShotFlight.MetresPerSecondPerMph, 0, 0);
            double carry = CarryFeet(Air.FromWeather(Baseline, Atmosphere.SeaLevelPressure, 0, headwind), _speed);
            AssertRoughly(carry - 400, -30, "10 mph headwind");
        }

        [Test]
        public void CoorsField_AddsAboutThirtyFeet()
        {
            // Denver, 5280 ft: the altitude rule gives 6 * 5.28 = +32 ft. Same temperature as the baseline.
            double denver = CarryFeet(Air.AtAltitude(1609, Baseline), _speed);
            AssertRoughly(denver - 400, 32, "Denver (5280 ft)");
        }
    }
}
