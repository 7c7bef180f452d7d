using System;
using System.Collections.Generic;
using System.Text.Json;
using MagnusBall.Aerodynamics;
using MagnusBall.Presets;

namespace MagnusBall.Cli
{
    /// <summary>
    /// The scenario fields of issue 7: "preset" (a sport's ball, aero and spin decay, each overridable by the
    /// explicit fields) and real air ("air": temperatureC, pressurePa, relativeHumidity or altitudeM instead of a
    /// density; "windProfile" for a logarithmic wind). Everything the scenario format accepted before reads as
    /// before; see docs/presets.md.
    /// </summary>
    internal static class PresetAndAirFields
    {
        /// <summary>The scenario's "preset", or null when absent.</summary>
        public static SportPreset? ReadPreset(JsonFields s)
        {
            if (!s.Has("preset"))
            {
                return null;
            }

            string name = s.String("preset");
            try
            {
                return SportPresets.FromName(name);
            }
            catch (ArgumentException)
            {
                throw new InputError(s.PathOf("preset"), $"unknown preset '{name}'; expected one of: {string.Join(", ", SportPresets.Names)}");
            }
        }

        /// <summary>
        /// The ball: required with mass and radius when there is no preset; with a preset, "ball" and each of its
        /// fields are optional and default to the preset's ball.
        /// </summary>
        public static Ball ReadBall(JsonFields s, SportPreset? preset)
        {
            JsonFields? fields = preset is null ? s.Object("ball") : s.OptionalObject("ball");
            if (fields is null)
            {
                return preset!.Ball;
            }

            double mass = preset is null ? fields.Positive("mass") : fields.Positive("mass", preset.Ball.Mass);
            double radius = preset is null ? fields.Positive("radius") : fields.Positive("radius", preset.Ball.Radius);
            double inertia = fields.Positive("inertiaFactor", preset?.Ball.InertiaFactor ?? Ball.SolidSphereInertiaFactor);
            if (inertia > 1)
            {
                throw new InputError(fields.PathOf("inertiaFactor"), "must be in (0, 1]; got " + JsonFields.Format(inertia));
            }

            fields.RejectUnknown();
            return new Ball(mass, radius, inertia);
        }

        /// <summary>
        /// The air: absent, ISA sea-level density; "density" (with "wind", "dynamicViscosity") as before; or the
        /// weather (temperatureC, pressurePa, relativeHumidity) or the altitude (altitudeM, with an optional
        /// temperatureC and relativeHumidity) instead of a density; plus an optional "windProfile".
        /// </summary>
        public static Air ReadAir(JsonFields s, double defaultDensity)
        {
            JsonFields? fields = s.OptionalObject("air");
            if (fields is null)
            {
                return new Air(defaultDensity);
            }

            bool hasDensity = fields.Optional("density").HasValue;
            bool hasTemperature = fields.Optional("temperatureC").HasValue;
            bool hasPressure = fields.Optional("pressurePa").HasValue;
            bool hasHumidity = fields.Optional("relativeHumidity").HasValue;
            bool hasAltitude = fields.Optional("altitudeM").HasValue;
            bool weather = hasTemperature || hasPressure || hasHumidity || hasAltitude;

            Air air;
            Vector3d wind;
            if (!weather)
            {
                double density = fields.NonNegative("density", defaultDensity);
                wind = fields.Vector("wind", Vector3d.Zero);
                double viscosity = fields.Positive("dynamicViscosity", Air.SeaLevelDynamicViscosity);
                air = new Air(density, wind, viscosity);
            }
            else
            {
                if (hasDensity)
                {
                    throw new InputError(fields.PathOf("density"),
                        "give either a density or the weather (temperatureC, pressurePa, relativeHumidity, altitudeM), not both");
                }

                if (hasAltitude && hasPressure)
                {
                    throw new InputError(fields.PathOf("pressurePa"), "altitudeM sets the pressure (ISA standard atmosphere); give one of them, not both");
                }

                wind = fields.Vector("wind", Vector3d.Zero);
                double humidity = fields.Number("relativeHumidity", 0);
                double? temperature = hasTemperature ? fields.Number("temperatureC") : (double?)null;
                try
                {
                    air = hasAltitude
                        ? Air.AtAltitude(fields.Number("altitudeM"), temperature, humidity, wind)
                        : Air.FromWeather(temperature ?? Atmosphere.SeaLevelTemperatureCelsius, fields.Number("pressurePa", Atmosphere.SeaLevelPressure), humidity, wind);
                }
                catch (ArgumentOutOfRangeException error)
                {
                    string field = error.ParamName switch
                    {
                        "temperatureCelsius" => "temperatureC",
                        "pressurePascals" => "pressurePa",
                        "altitudeMetres" => "altitudeM",
                        _ => error.ParamName ?? string.Empty,
                    };
                    // The library's message reads "<parameter> must be ...; got ..." (+ .NET's parameter suffix):
                    // keep the range and the value, and name the JSON field instead.
                    string problem = error.Message.Split('\n')[0];
                    int cut = problem.IndexOf(" (Parameter", StringComparison.Ordinal);
                    problem = cut >= 0 ? problem.Substring(0, cut) : problem;
                    string prefix = (error.ParamName ?? string.Empty) + " ";
                    problem = problem.StartsWith(prefix, StringComparison.Ordinal) ? problem.Substring(prefix.Length) : problem;
                    throw new InputError(fields.PathOf(field), problem);
                }

                if (fields.Optional("dynamicViscosity").HasValue)
                {
                    air = new Air(air.Density, wind, fields.Positive("dynamicViscosity"));
                }
            }

            JsonFields? profile = fields.OptionalObject("windProfile");
            if (profile != null)
            {
                double referenceHeight = profile.Positive("referenceHeight", LogarithmicWindProfile.StandardReferenceHeight);
                double roughness = profile.Positive("roughnessLength", LogarithmicWindProfile.OpenGrassRoughnessLength);
                Vector3d groundPoint = profile.Vector("groundPoint", Vector3d.Zero);
                if (!(referenceHeight > roughness))
                {
                    throw new InputError(profile.PathOf("referenceHeight"),
                        $"must be greater than roughnessLength ({JsonFields.Format(roughness)}); got {JsonFields.Format(referenceHeight)}");
                }

                profile.RejectUnknown();
                air = air.WithLogarithmicWind(wind, referenceHeight, roughness, groundPoint);
            }

            fields.RejectUnknown();
            return air;
        }

        /// <summary>
        /// A tabulated lift law, {"model": "table", "points": [[S, C_L], ...]}: S increasing from &gt;= 0, linear
        /// between points, held at the end values outside (<see cref="PiecewiseLinearLift"/>).
        /// </summary>
        public static PiecewiseLinearLift ReadLiftTable(JsonFields fields)
        {
            JsonElement points = fields.Required("points");
            string path = fields.PathOf("points");
            if (points.ValueKind != JsonValueKind.Array || points.GetArrayLength() == 0)
            {
                throw new InputError(path, "must be a non-empty array of [S, C_L] pairs; got " + JsonFields.Describe(points));
            }

            var s = new List<double>();
            var c = new List<double>();
            int i = 0;
            foreach (JsonElement point in points.EnumerateArray())
            {
                string pointPath = $"{path}[{i}]";
                if (point.ValueKind != JsonValueKind.Array || point.GetArrayLength() != 2)
                {
                    throw new InputError(pointPath, "must be a pair [S, C_L] of finite numbers; got " + JsonFields.Describe(point));
                }

                double spin = JsonFields.ReadNumber(point[0], pointPath + "[0]");
                if (spin < 0 || (s.Count > 0 && !(spin > s[s.Count - 1])))
                {
                    throw new InputError(pointPath + "[0]", "spin parameters must be >= 0 and strictly increasing; got " + JsonFields.Format(spin));
                }

                s.Add(spin);
                c.Add(JsonFields.ReadNumber(point[1], pointPath + "[1]"));
                i++;
            }

            return new PiecewiseLinearLift(s, c);
        }
    }
}
