using System;
using NUnit.Framework;

namespace MagnusBall.Tests.Aerodynamics
{
    /// <summary>Air from the weather and from altitude (moist-air density, ISA, Sutherland).</summary>
    [TestFixture]
    public class AtmosphereTests
    {
        [Test]
        public void DryAirAt15CAnd101325Pa_Is1Point225()
        {
            // 0.001 kg/m^3: the check; the ideal-gas value is 101325/(287.058*288.15) = 1.22498.
            Assert.That(Air.FromWeather(15, 101325).Density, Is.EqualTo(1.225).Within(0.001));
            Assert.That(Air.AtAltitude(0).Density, Is.EqualTo(1.225).Within(0.001));
        }

        [TestCase(0.0)]
        [TestCase(15.0)]
        [TestCase(30.0)]
        public void HumidAir_IsLighterThanDryAir_AtTheSameTemperatureAndPressure(double temperatureCelsius)
        {
            double dry = Air.FromWeather(temperatureCelsius, 101325, 0).Density;
            double half = Air.FromWeather(temperatureCelsius, 101325, 0.5).Density;
            double saturated = Air.FromWeather(temperatureCelsius, 101325, 1).Density;
            Assert.That(half, Is.LessThan(dry));
            Assert.That(saturated, Is.LessThan(half));
            // Vapour replaces dry air molecule for molecule: rho drops by e (1/R_d - 1/R_v)/T. At 30 degC,
            // saturated: e = 4243 Pa (Tetens), so 4243 * (1/287.058 - 1/461.495) / 303.15 = 0.0184 kg/m^3.
            // 1e-4: rounding of the worked number.
            if (temperatureCelsius == 30.0)
            {
                Assert.That(dry - saturated, Is.EqualTo(0.0184).Within(1e-4));
            }
        }

        [Test]
        public void TetensSaturationPressure_MatchesTabulatedValues()
        {
            // Tabulated (Goff-Gratch / WMO) saturation pressures over water: 611.2 Pa at 0 degC, 2339 Pa at
            // 20 degC, 4246 Pa at 30 degC. 0.5 %: Tetens' stated accuracy over 0-35 degC.
            Assert.That(Atmosphere.SaturationVapourPressure(0), Is.EqualTo(611.2).Within(0.5).Percent);
            Assert.That(Atmosphere.SaturationVapourPressure(20), Is.EqualTo(2339).Within(0.5).Percent);
            Assert.That(Atmosphere.SaturationVapourPressure(30), Is.EqualTo(4246).Within(0.5).Percent);
        }

        [Test]
        public void Denver_IsAbout18PercentThinnerAtTheSameTemperature_And14PercentInTheStandardAtmosphere()
        {
            // Denver, 1609 m (5280 ft). The "18 % thinner" usually quoted compares air at the same temperature:
            // it is the pressure ratio, (1 - 0.0065*1609/288.15)^5.2559 = 0.8234.
            double sameTemperature = Air.AtAltitude(1609, 15).Density / Air.AtAltitude(0, 15).Density;
            // 0.01: "about 18 %" is a rounded figure; 0.8234 is the ISA pressure ratio.
            Assert.That(1 - sameTemperature, Is.EqualTo(0.18).Within(0.01));
            // With the ISA lapse rate Denver's air is also 10.5 K colder, which gives back 3.1 points.
            double standard = Air.AtAltitude(1609).Density / Air.SeaLevel.Density;
            // 1e-3: the ISA ratio worked by hand, 83431 Pa / (287.058 * 277.69 K) / 1.22498 = 0.8544.
            Assert.That(standard, Is.EqualTo(0.8544).Within(1e-3));
        }

        [Test]
        public void StandardAtmosphere_KnownPointsAndContinuityAtTheTropopause()
        {
            // ISA table (ICAO Doc 7488): 5000 m -> 54,020 Pa, -17.5 degC; 11,000 m -> 22,632 Pa; 20,000 m -> 5,475 Pa.
            // 0.1 %: the table's rounding and R_d = 287.058 against the ISA's 287.053.
            Assert.That(Atmosphere.StandardPressure(5000), Is.EqualTo(54020).Within(0.1).Percent);
            Assert.That(Atmosphere.StandardTemperatureCelsius(5000), Is.EqualTo(-17.5).Within(1e-9));
            Assert.That(Atmosphere.StandardPressure(11000), Is.EqualTo(22632).Within(0.1).Percent);
            Assert.That(Atmosphere.StandardPressure(20000), Is.EqualTo(5475).Within(0.1).Percent);
            double below = Atmosphere.StandardPressure(11000 - 1e-6);
            double above = Atmosphere.StandardPressure(11000 + 1e-6);
            // 1e-6 relative: the two layers meet; over 2 um the pressure changes by 2.4e-10 relative.
            Assert.That(above / below, Is.EqualTo(1).Within(1e-6));
        }

        [Test]
        public void SutherlandViscosity_At15C()
        {
            // ISA table: 1.7894e-5 Pa s at 15 degC. 1e-8: the table's rounding.
            Assert.That(Atmosphere.DynamicViscosity(15), Is.EqualTo(1.7894e-5).Within(1e-8));
            Assert.That(Air.FromWeather(15, 101325).DynamicViscosity, Is.EqualTo(Atmosphere.DynamicViscosity(15)));
        }

        [Test]
        public void BadWeather_IsRefusedNamingTheParameter()
        {
            Assert.That(() => Air.FromWeather(double.NaN, 101325), Throws.InstanceOf<ArgumentException>().With.Message.Contains("temperatureCelsius"));
            Assert.That(() => Air.FromWeather(100, 101325), Throws.InstanceOf<ArgumentException>().With.Message.Contains("temperatureCelsius"));
            Assert.That(() => Air.FromWeather(15, 0), Throws.InstanceOf<ArgumentException>().With.Message.Contains("pressurePascals"));
            Assert.That(() => Air.FromWeather(15, 101325, 1.5), Throws.InstanceOf<ArgumentException>().With.Message.Contains("relativeHumidity"));
            Assert.That(() => Air.FromWeather(15, 101325, -0.1), Throws.InstanceOf<ArgumentException>().With.Message.Contains("relativeHumidity"));
            // A vapour pressure above the total pressure is the pressure's fault (a value in kPa, hPa or far below any
            // station): 5000 Pa at 50 degC saturated, and the 101.325 (kPa) at 20 degC and 50 %.
            Assert.That(() => Air.FromWeather(50, 5000, 1), Throws.InstanceOf<ArgumentException>().With.Property("ParamName").EqualTo("pressurePascals"));
            Assert.That(() => Air.FromWeather(20, 101.325, 0.5), Throws.InstanceOf<ArgumentException>()
                .With.Property("ParamName").EqualTo("pressurePascals").And.Message.Contains("kPa"));
            // In hPa, dry and cool (the vapour pressure is no help there): below the 5000 Pa floor, the air at 20 km.
            Assert.That(() => Air.FromWeather(15, 1013.25, 0), Throws.InstanceOf<ArgumentException>()
                .With.Property("ParamName").EqualTo("pressurePascals").And.Message.Contains("hPa"));
            Assert.That(Air.AtAltitude(20000).Density, Is.GreaterThan(0), "AtAltitude's top is above the floor");
            // AtAltitude takes no pressure: there the humidity is named (60 degC saturated at 20 km, 5.5 kPa).
            Assert.That(() => Air.AtAltitude(20000, 60, 1), Throws.InstanceOf<ArgumentException>()
                .With.Property("ParamName").EqualTo("relativeHumidity").And.Message.Contains("must be below 0.27"));
            Assert.That(() => Air.AtAltitude(30000), Throws.InstanceOf<ArgumentException>().With.Message.Contains("altitudeMetres"));
            Assert.That(() => Air.AtAltitude(double.PositiveInfinity), Throws.InstanceOf<ArgumentException>().With.Message.Contains("altitudeMetres"));
            Assert.That(() => Air.FromWeather(15, 101325, 0, new Vector3d(double.NaN, 0, 0)), Throws.InstanceOf<ArgumentException>().With.Message.Contains("wind"));
        }
    }
}
