using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace MagnusBall.Playground.Lab
{
    /// <summary>What the second shot is, drawn beside the first.</summary>
    public enum CompareWith
    {
        /// <summary>No second shot.</summary>
        None,

        /// <summary>The same shot without spin (Cross's topspin figure).</summary>
        NoSpin,

        /// <summary>The same shot with another integrator and step.</summary>
        OtherIntegrator,
    }

    /// <summary>
    /// Every input of the playground, in the units a player uses (m/s, degrees, rpm, m, degC, %), with the ranges
    /// the page accepts, and their round trip through the address's query (a shareable link).
    /// </summary>
    public sealed class ShotSettings
    {
        /// <summary>A field the page accepts: its query key, label, unit and allowed range.</summary>
        public sealed class Field
        {
            internal Field(string key, string label, double minimum, double maximum, Func<ShotSettings, double> get, Action<ShotSettings, double> set)
            {
                Key = key;
                Label = label;
                Minimum = minimum;
                Maximum = maximum;
                Get = get;
                Set = set;
            }

            /// <summary>The query key (and the input's id, "in-" + key).</summary>
            public string Key { get; }

            /// <summary>The label with its unit.</summary>
            public string Label { get; }

            /// <summary>Lowest value accepted.</summary>
            public double Minimum { get; }

            /// <summary>Highest value accepted.</summary>
            public double Maximum { get; }

            /// <summary>Reads the field.</summary>
            public Func<ShotSettings, double> Get { get; }

            /// <summary>Writes the field.</summary>
            public Action<ShotSettings, double> Set { get; }

            /// <summary>Why <paramref name="value"/> is refused, or null if it is accepted.</summary>
            public string? Refusal(double value) =>
                double.IsFinite(value) && value >= Minimum && value <= Maximum
                    ? null
                    : $"{Label} must be from {Format(Minimum)} to {Format(Maximum)}; got {Format(value)}.";
        }

        /// <summary>The numeric fields, in the order the form shows them.</summary>
        public static IReadOnlyList<Field> Fields { get; } = new[]
        {
            new Field("speed", "Speed (m/s)", 0.5, 100, s => s.SpeedMetresPerSecond, (s, v) => s.SpeedMetresPerSecond = v),
            new Field("elev", "Elevation (deg)", -45, 89, s => s.ElevationDegrees, (s, v) => s.ElevationDegrees = v),
            new Field("dir", "Direction (deg, + left)", -60, 60, s => s.DirectionDegrees, (s, v) => s.DirectionDegrees = v),
            new Field("top", "Topspin (rpm, - backspin)", -12000, 12000, s => s.TopspinRpm, (s, v) => s.TopspinRpm = v),
            new Field("side", "Sidespin (rpm, + curls left)", -12000, 12000, s => s.SidespinRpm, (s, v) => s.SidespinRpm = v),
            new Field("h", "Launch height (m)", 0, 5, s => s.LaunchHeightMetres, (s, v) => s.LaunchHeightMetres = v),
            new Field("alt", "Altitude (m)", -400, 5000, s => s.AltitudeMetres, (s, v) => s.AltitudeMetres = v),
            new Field("temp", "Temperature (degC)", -30, 50, s => s.TemperatureCelsius, (s, v) => s.TemperatureCelsius = v),
            new Field("rh", "Humidity (%)", 0, 100, s => s.HumidityPercent, (s, v) => s.HumidityPercent = v),
            new Field("tail", "Tailwind (m/s, - headwind)", -30, 30, s => s.TailwindMetresPerSecond, (s, v) => s.TailwindMetresPerSecond = v),
            new Field("cross", "Crosswind (m/s, + to the left)", -30, 30, s => s.CrosswindMetresPerSecond, (s, v) => s.CrosswindMetresPerSecond = v),
            new Field("rate", "Steps per second (1/s)", 10, 10000, s => s.StepsPerSecond, (s, v) => s.StepsPerSecond = v),
            new Field("rate2", "Its steps per second (1/s)", 10, 10000, s => s.CompareStepsPerSecond, (s, v) => s.CompareStepsPerSecond = v),
        };

        /// <summary>The preset's name (one of <see cref="MagnusBall.Presets.SportPresets.Names"/>).</summary>
        public string Preset { get; set; } = "tennis";

        /// <summary>Launch speed, m/s.</summary>
        public double SpeedMetresPerSecond { get; set; } = 30;

        /// <summary>Launch elevation above the horizontal, degrees.</summary>
        public double ElevationDegrees { get; set; } = 6;

        /// <summary>Launch direction from the forward axis (downrange), degrees, positive to the left.</summary>
        public double DirectionDegrees { get; set; }

        /// <summary>Topspin, rpm (negative: backspin).</summary>
        public double TopspinRpm { get; set; } = 1200;

        /// <summary>Sidespin, rpm (positive: the ball curls to the left).</summary>
        public double SidespinRpm { get; set; }

        /// <summary>Height of the ball's centre at launch above the playing surface, m.</summary>
        public double LaunchHeightMetres { get; set; } = 1;

        /// <summary>Altitude above sea level, m (standard-atmosphere pressure).</summary>
        public double AltitudeMetres { get; set; }

        /// <summary>Air temperature, degC.</summary>
        public double TemperatureCelsius { get; set; } = 15;

        /// <summary>Relative humidity, %.</summary>
        public double HumidityPercent { get; set; } = 50;

        /// <summary>Wind along the shot, m/s (negative: into the player's face).</summary>
        public double TailwindMetresPerSecond { get; set; }

        /// <summary>Wind across the shot, m/s, positive toward the left.</summary>
        public double CrosswindMetresPerSecond { get; set; }

        /// <summary>The integrator's name (one of <see cref="MagnusBall.Integration.Integrators.Names"/>).</summary>
        public string Integrator { get; set; } = "rk4";

        /// <summary>Fixed steps per second, 1/s (a game's physics rate: 60, 120, 240...).</summary>
        public double StepsPerSecond { get; set; } = 240;

        /// <summary>The fixed step, s: 1 / <see cref="StepsPerSecond"/>.</summary>
        public double StepSeconds => 1.0 / StepsPerSecond;

        /// <summary>What the second shot is.</summary>
        public CompareWith Compare { get; set; } = CompareWith.NoSpin;

        /// <summary>The second shot's integrator, where <see cref="Compare"/> is <see cref="CompareWith.OtherIntegrator"/>.</summary>
        public string CompareIntegrator { get; set; } = "euler";

        /// <summary>The second shot's fixed steps per second, 1/s.</summary>
        public double CompareStepsPerSecond { get; set; } = 60;

        /// <summary>The second shot's step, s.</summary>
        public double CompareStepSeconds => 1.0 / CompareStepsPerSecond;

        /// <summary>The longest flight, s (not an input: the scene's).</summary>
        public double MaxFlightSeconds { get; set; } = 8;

        /// <summary>A copy.</summary>
        public ShotSettings Clone() => (ShotSettings)MemberwiseClone();

        /// <summary>This preset's scene's launch, with this air, integrator and comparison.</summary>
        public ShotSettings WithSceneLaunch(string preset)
        {
            ShotSettings launch = Scene.For(preset).Launch;
            ShotSettings s = Clone();
            s.Preset = preset;
            s.SpeedMetresPerSecond = launch.SpeedMetresPerSecond;
            s.ElevationDegrees = launch.ElevationDegrees;
            s.DirectionDegrees = launch.DirectionDegrees;
            s.TopspinRpm = launch.TopspinRpm;
            s.SidespinRpm = launch.SidespinRpm;
            s.LaunchHeightMetres = launch.LaunchHeightMetres;
            s.MaxFlightSeconds = launch.MaxFlightSeconds;
            return s;
        }

        /// <summary>The settings as an address query ("preset=tennis&amp;speed=30&amp;..."), numbers round-trip exact.</summary>
        public string ToQuery()
        {
            var q = new StringBuilder();
            q.Append("preset=").Append(Uri.EscapeDataString(Preset));
            foreach (Field f in Fields)
            {
                q.Append('&').Append(f.Key).Append('=').Append(Uri.EscapeDataString(Format(f.Get(this))));
            }

            q.Append("&method=").Append(Uri.EscapeDataString(Integrator));
            q.Append("&cmp=").Append(Compare switch { CompareWith.None => "none", CompareWith.NoSpin => "nospin", _ => "method" });
            q.Append("&method2=").Append(Uri.EscapeDataString(CompareIntegrator));
            return q.ToString();
        }

        /// <summary>
        /// Reads an address query written by <see cref="ToQuery"/> (any subset of keys; the others keep the preset
        /// scene's defaults). Refused values are listed in <paramref name="refusals"/> and left at their defaults.
        /// </summary>
        public static ShotSettings FromQuery(string query, List<string> refusals)
        {
            Dictionary<string, string> values = Parse(query);
            string preset = values.TryGetValue("preset", out string? p) ? p : "tennis";
            if (!Array.Exists(Lab.Names.Presets, n => n == preset))
            {
                refusals.Add($"Preset must be one of {string.Join(", ", Lab.Names.Presets)}; got '{preset}'.");
                preset = "tennis";
            }

            ShotSettings s = new ShotSettings().WithSceneLaunch(preset);
            foreach (Field f in Fields)
            {
                if (!values.TryGetValue(f.Key, out string? text))
                {
                    continue;
                }

                if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double v))
                {
                    refusals.Add($"{f.Label} must be a number; got '{text}'.");
                    continue;
                }

                string? why = f.Refusal(v);
                if (why is null)
                {
                    f.Set(s, v);
                }
                else
                {
                    refusals.Add(why);
                }
            }

            s.Integrator = Known(values, "method", s.Integrator, refusals);
            s.CompareIntegrator = Known(values, "method2", s.CompareIntegrator, refusals);
            if (values.TryGetValue("cmp", out string? cmp))
            {
                switch (cmp)
                {
                    case "none": s.Compare = CompareWith.None; break;
                    case "nospin": s.Compare = CompareWith.NoSpin; break;
                    case "method": s.Compare = CompareWith.OtherIntegrator; break;
                    default: refusals.Add($"Second shot must be none, nospin or method; got '{cmp}'."); break;
                }
            }

            return s;
        }

        /// <summary>Why these settings are refused (a field out of the range the page accepts), or null: what the address can carry.</summary>
        public string? Refusal()
        {
            foreach (Field f in Fields)
            {
                string? why = f.Refusal(f.Get(this));
                if (why is not null)
                {
                    return why;
                }
            }

            return null;
        }

        /// <summary>A number as the page writes it: invariant culture, shortest round-trip form.</summary>
        public static string Format(double value) => value.ToString("R", CultureInfo.InvariantCulture);

        private static string Known(Dictionary<string, string> values, string key, string fallback, List<string> refusals)
        {
            if (!values.TryGetValue(key, out string? name))
            {
                return fallback;
            }

            if (Array.Exists(Lab.Names.Integrators, n => n == name))
            {
                return name;
            }

            refusals.Add($"Integrator must be one of {string.Join(", ", Lab.Names.Integrators)}; got '{name}'.");
            return fallback;
        }

        /// <summary>The value of <paramref name="key"/> in an address query, or null where the query has no such key.</summary>
        public static string? QueryValue(string query, string key) => Parse(query).TryGetValue(key, out string? v) ? v : null;

        private static Dictionary<string, string> Parse(string query)
        {
            var values = new Dictionary<string, string>(StringComparer.Ordinal);
            string q = query.StartsWith("?", StringComparison.Ordinal) ? query.Substring(1) : query;
            foreach (string pair in q.Split('&', StringSplitOptions.RemoveEmptyEntries))
            {
                int eq = pair.IndexOf('=');
                string key = Uri.UnescapeDataString((eq < 0 ? pair : pair.Substring(0, eq)).Replace('+', ' '));
                string value = eq < 0 ? string.Empty : Uri.UnescapeDataString(pair.Substring(eq + 1).Replace('+', ' '));
                values[key] = value;
            }

            return values;
        }
    }

    /// <summary>The names the page offers, from the library's own lists.</summary>
    public static class Names
    {
        /// <summary>Every preset's name.</summary>
        public static readonly string[] Presets = ToArray(MagnusBall.Presets.SportPresets.Names);

        /// <summary>Every fixed-step integrator's name.</summary>
        public static readonly string[] Integrators = MagnusBall.Integration.Integrators.Names;

        private static string[] ToArray(IReadOnlyList<string> list)
        {
            var a = new string[list.Count];
            for (int i = 0; i < a.Length; i++)
            {
                a[i] = list[i];
            }

            return a;
        }
    }
}
