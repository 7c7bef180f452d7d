using System;

namespace MagnusBall
{
    /// <summary>
    /// Air properties from the weather and from altitude: moist-air density, saturation vapour pressure,
    /// the ISA standard atmosphere and the viscosity of air. Pure functions; <see cref="Air.FromWeather"/>
    /// and <see cref="Air.AtAltitude"/> build an <see cref="Air"/> from them.
    /// </summary>
    /// <remarks>
    /// <para>Moist air is treated as a mixture of two ideal gases: with vapour pressure e = RH e_s(T),
    /// rho = (p - e) / (R_d T) + e / (R_v T), R_d = 287.058 J/(kg K), R_v = 461.495 J/(kg K). Water vapour is
    /// lighter than the dry air it replaces (18 g/mol against 29), so humid air is less dense at the same
    /// temperature and pressure.</para>
    /// <para>Saturation vapour pressure: Tetens (1930), in the form of Murray (1967),
    /// e_s = 610.78 exp(17.27 T / (T + 237.3)) Pa with T in degC (within about 0.1 % of the Goff-Gratch
    /// values over water between 0 and 35 degC; over water also below 0 degC).</para>
    /// <para>Standard atmosphere: ISO 2533:1975 (ICAO/ISA): sea level 288.15 K and 101325 Pa, lapse rate
    /// 6.5 K/km up to 11 km, isothermal 216.65 K from 11 to 20 km. Altitudes are geopotential; geometric altitude z
    /// is higher by the fraction z / (r_earth + z): below 0.04 % at sports altitudes (up to 2.4 km), 0.1 % at 6.4 km and
    /// 0.31 % at 20 km (the density at 15 km then differs from a geometric-altitude table by about 0.6 %).</para>
    /// <para>Viscosity: Sutherland's law, mu = 1.458e-6 T^1.5 / (T + 110.4) Pa s (the ISA's own formula),
    /// 1.789e-5 Pa s at 15 degC.</para>
    /// </remarks>
    internal static class Atmosphere
    {
        /// <summary>Specific gas constant of dry air, 287.058 J/(kg K).</summary>
        internal const double DryAirGasConstant = 287.058;

        /// <summary>Specific gas constant of water vapour, 461.495 J/(kg K).</summary>
        internal const double WaterVapourGasConstant = 461.495;

        /// <summary>ISA sea-level pressure, 101325 Pa.</summary>
        public const double SeaLevelPressure = 101325.0;

        /// <summary>ISA sea-level temperature, 15 degC (288.15 K).</summary>
        public const double SeaLevelTemperatureCelsius = 15.0;

        /// <summary>0 degC in kelvin, 273.15 K.</summary>
        internal const double ZeroCelsiusInKelvin = 273.15;

        /// <summary>ISA tropospheric lapse rate, 0.0065 K/m.</summary>
        internal const double TroposphereLapseRate = 0.0065;

        /// <summary>Top of the ISA troposphere, 11000 m.</summary>
        internal const double TropopauseAltitude = 11000.0;

        /// <summary>Lowest altitude accepted, -1000 m (the Dead Sea shore is at about -430 m).</summary>
        public const double MinimumAltitude = -1000.0;

        /// <summary>Highest altitude accepted, 20000 m (the top of the ISA's isothermal layer).</summary>
        public const double MaximumAltitude = 20000.0;

        /// <summary>Lowest temperature accepted, -90 degC.</summary>
        public const double MinimumTemperatureCelsius = -90.0;

        /// <summary>Highest temperature accepted, 60 degC.</summary>
        public const double MaximumTemperatureCelsius = 60.0;

        // The lowest station pressure taken, Pa: below the ISA's 5474.9 Pa at 20 km (AtAltitude's top), above any pressure
        // in kPa (about 101) or hPa (about 1013) given by mistake.
        private const double MinimumPressurePascals = 5000.0;

        // g0 M / (R* L) for the ISA troposphere: 9.80665 * 0.0289644 / (8.31432 * 0.0065), with the ISA's R* = 8.31432.
        private const double PressureExponent = 5.255877;

        // g0 / R_d for the isothermal layer (R_d = 287.058, within 2e-5 of the ISA's 287.05287).
        private const double IsothermalScale = Gravity.Standard / DryAirGasConstant;

        /// <summary>
        /// Saturation vapour pressure of water over a flat water surface, Pa (Tetens 1930, Murray 1967 form):
        /// 610.78 exp(17.27 T / (T + 237.3)).
        /// </summary>
        /// <param name="temperatureCelsius">Temperature, degC; in [-90, 60].</param>
        /// <exception cref="ArgumentOutOfRangeException">The temperature is out of range.</exception>
        public static double SaturationVapourPressure(double temperatureCelsius)
        {
            Require.InRange(temperatureCelsius, MinimumTemperatureCelsius, MaximumTemperatureCelsius, nameof(temperatureCelsius));
            return 610.78 * PortableMath.Exp(17.27 * temperatureCelsius / (temperatureCelsius + 237.3));
        }

        /// <summary>
        /// Density of moist air, kg/m^3: rho = (p - e)/(R_d T) + e/(R_v T) with e = RH e_s(T) (Tetens).
        /// 15 degC, 101325 Pa, dry: 1.2250 kg/m^3.
        /// </summary>
        /// <param name="temperatureCelsius">Temperature, degC; in [-90, 60].</param>
        /// <param name="pressurePascals">Total (station) pressure, Pa; finite and at least 5000 (the air at 20 km), so that a
        /// pressure given in kPa or hPa by mistake is refused.</param>
        /// <param name="relativeHumidity">Relative humidity as a fraction, in [0, 1] (0.5 is 50 %).</param>
        /// <exception cref="ArgumentOutOfRangeException">A value is out of range, or the pressure is not above the vapour
        /// pressure (a pressure in kPa or hPa by mistake; the message names pressurePascals).</exception>
        public static double MoistAirDensity(double temperatureCelsius, double pressurePascals, double relativeHumidity = 0)
        {
            Require.InRange(temperatureCelsius, MinimumTemperatureCelsius, MaximumTemperatureCelsius, nameof(temperatureCelsius));
            if (!(pressurePascals >= MinimumPressurePascals) || double.IsPositiveInfinity(pressurePascals))
            {
                throw new ArgumentOutOfRangeException(
                    nameof(pressurePascals),
                    pressurePascals,
                    $"pressurePascals must be a finite pressure of at least {Require.Format(MinimumPressurePascals)} Pa (the air at 20 km, the " +
                    $"highest altitude AtAltitude takes); got {Require.Format(pressurePascals)} Pa. Station pressures on the ground are about " +
                    "30000-110000 Pa: was it given in kPa or hPa (101.325 kPa = 1013.25 hPa = 101325 Pa)?");
            }

            double vapour = VapourPressure(temperatureCelsius, relativeHumidity);
            if (vapour >= pressurePascals)
            {
                // The vapour pressure is at most 20 kPa (saturation at 60 degC), below any station pressure on Earth
                // (about 33 kPa on Everest): the pressure is the value in the wrong unit, not the humidity.
                throw new ArgumentOutOfRangeException(
                    nameof(pressurePascals),
                    pressurePascals,
                    $"pressurePascals must be above the water-vapour pressure of this air ({Require.Format(vapour)} Pa at " +
                    $"{Require.Format(temperatureCelsius)} degC and relative humidity {Require.Format(relativeHumidity)}); got " +
                    $"{Require.Format(pressurePascals)} Pa. Station pressures are about 30000-110000 Pa: was it given in kPa or hPa " +
                    "(101.325 kPa = 1013.25 hPa = 101325 Pa)?");
            }

            double kelvin = temperatureCelsius + ZeroCelsiusInKelvin;
            return (pressurePascals - vapour) / (DryAirGasConstant * kelvin) + vapour / (WaterVapourGasConstant * kelvin);
        }

        /// <summary>
        /// The water-vapour partial pressure of air at <paramref name="relativeHumidity"/>, Pa: RH e_s(T) (Tetens), the part
        /// of the total pressure that <see cref="MoistAirDensity"/> counts as vapour and that must stay below it.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">The humidity is outside [0, 1] or the temperature out of range.</exception>
        internal static double VapourPressure(double temperatureCelsius, double relativeHumidity)
        {
            Require.InRange(relativeHumidity, 0, 1, nameof(relativeHumidity));
            return relativeHumidity * SaturationVapourPressure(temperatureCelsius);
        }

        /// <summary>ISA temperature at an altitude, degC: 15 - 6.5 per km up to 11 km, then -56.5.</summary>
        /// <param name="altitudeMetres">Geopotential altitude above mean sea level, m; in [-1000, 20000].</param>
        /// <exception cref="ArgumentOutOfRangeException">The altitude is out of range.</exception>
        public static double StandardTemperatureCelsius(double altitudeMetres)
        {
            Require.InRange(altitudeMetres, MinimumAltitude, MaximumAltitude, nameof(altitudeMetres));
            double h = Math.Min(altitudeMetres, TropopauseAltitude);
            return SeaLevelTemperatureCelsius - TroposphereLapseRate * h;
        }

        /// <summary>
        /// ISA pressure at an altitude, Pa: 101325 (T/288.15)^5.2559 in the troposphere, exponential above
        /// 11 km. 1609 m (Denver): 83,431 Pa.
        /// </summary>
        /// <param name="altitudeMetres">Geopotential altitude above mean sea level, m; in [-1000, 20000].</param>
        /// <exception cref="ArgumentOutOfRangeException">The altitude is out of range.</exception>
        public static double StandardPressure(double altitudeMetres)
        {
            Require.InRange(altitudeMetres, MinimumAltitude, MaximumAltitude, nameof(altitudeMetres));
            const double seaLevelKelvin = SeaLevelTemperatureCelsius + ZeroCelsiusInKelvin;
            double h = Math.Min(altitudeMetres, TropopauseAltitude);
            double pressure = SeaLevelPressure * PortableMath.Pow(1 - TroposphereLapseRate * h / seaLevelKelvin, PressureExponent);
            if (altitudeMetres > TropopauseAltitude)
            {
                double tropopauseKelvin = seaLevelKelvin - TroposphereLapseRate * TropopauseAltitude;
                pressure *= PortableMath.Exp(-IsothermalScale * (altitudeMetres - TropopauseAltitude) / tropopauseKelvin);
            }

            return pressure;
        }

        /// <summary>
        /// Dynamic viscosity of air, Pa s, by Sutherland's law: 1.458e-6 T^1.5 / (T + 110.4), T in kelvin
        /// (1.789e-5 Pa s at 15 degC). Humidity changes it by well under 1 % and is ignored.
        /// </summary>
        /// <param name="temperatureCelsius">Temperature, degC; in [-90, 60].</param>
        /// <exception cref="ArgumentOutOfRangeException">The temperature is out of range.</exception>
        public static double DynamicViscosity(double temperatureCelsius)
        {
            Require.InRange(temperatureCelsius, MinimumTemperatureCelsius, MaximumTemperatureCelsius, nameof(temperatureCelsius));
            double kelvin = temperatureCelsius + ZeroCelsiusInKelvin;
            return 1.458e-6 * kelvin * Math.Sqrt(kelvin) / (kelvin + 110.4);
        }
    }
}
