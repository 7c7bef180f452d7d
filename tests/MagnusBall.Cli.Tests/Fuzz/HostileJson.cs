using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;
using System.Text.Json.Nodes;

namespace MagnusBall.Fuzz
{
    /// <summary>
    /// Seeded hostile scenario files for the CLI (issue 15): a valid drive mutated one to four times with bad types,
    /// huge and tiny numbers, nulls, lone surrogates, control characters, unknown and duplicated fields, deep nesting,
    /// truncated text, extreme vectors, every integrator and model. Shared by the suite's fuzz test and the
    /// benchmark project's long run (linked there as a source file).
    /// </summary>
    public sealed class HostileJson
    {
        private static readonly double[] Numbers =
        {
            0, -0.0, 5e-324, -5e-324, 1e-320, 1e-300, 1e-160, 1e-100, 1e-9, 1e-6, 1e-3, 0.5, 1, -1, 2, 3, 10, 100, 1e3, 1e6,
            1e9, 1e12, 1e15, 1e17, 1e100, 1e154, 1e155, 1e160, 1e200, 1e300, 1.7976931348623157e308, -1.7976931348623157e308, -1e155,
        };

        private static readonly string[] Strings =
        {
            "", "rk4", "stable-rk4", "euler", "semi-implicit-euler", "heun", "dp54", "RK4", "rk45", "constant", "stepanek", "none", "table",
            "nathan", "goff-carre", "linear-spin", "exponential", "speed-proportional", "smits-smith-golf", "tennis", "golf", "soccer",
            "\u0000", "\u0001x", "a\uffffb", "\ufffe", "\U0001F3BE", "net\u001b[31m", "<&>\"'", "NaN", "Infinity", "1e999",
        };

        private static readonly string[] Paths =
        {
            "name", "ball", "ball.mass", "ball.radius", "ball.inertiaFactor", "air", "air.density", "air.wind", "air.dynamicViscosity",
            "air.temperatureC", "air.pressurePa", "air.relativeHumidity", "air.altitudeM", "air.windProfile", "gravity", "aero",
            "aero.drag", "aero.drag.model", "aero.drag.cd", "aero.lift", "aero.lift.model", "aero.lift.cl", "spinDecay", "spinDecay.model",
            "spinDecay.tau", "initial", "initial.position", "initial.velocity", "initial.angularVelocity", "initial.time", "integrator",
            "step", "maxTime", "ground", "ground.point", "ground.normal", "planes", "planes[0].name", "planes[0].point", "planes[0].normal",
            "planes[0].bounds", "preset",
        };

        private readonly Random _random;

        /// <summary>Creates a generator; the same seed gives the same files.</summary>
        public HostileJson(int seed) => _random = new Random(seed);

        /// <summary>
        /// Accepted flights are kept to at most this many steps (maxTime shortened), so a run stays short; the CLI's
        /// own caps (1e7 steps a scenario and a file) are tested on their own. 0 leaves maxTime as mutated.
        /// </summary>
        public double MaxStepsKept { get; set; } = 1e5;

        /// <summary>The next file's text.</summary>
        public string Next()
        {
            JsonObject root = JsonNode.Parse(Base)!.AsObject();
            var scenario = root["scenarios"]![0]!.AsObject();
            int mutations = 1 + _random.Next(4);
            string? raw = null;
            for (int m = 0; m < mutations; m++)
            {
                switch (_random.Next(12))
                {
                    case 0:
                    case 1:
                    case 2:
                    case 3:
                        Set(scenario, Pick(Paths), Value(0));
                        break;
                    case 4:
                        Set(scenario, Pick(new[] { "initial.position", "initial.velocity", "initial.angularVelocity", "gravity", "air.wind", "ground.normal", "planes[0].normal" }),
                            new JsonArray(Number(), Number(), Number()));
                        break;
                    case 5:
                        Set(scenario, Pick(new[] { "step", "maxTime", "ball.mass", "ball.radius", "air.density", "initial.time", "spinDecay.tau" }), Number());
                        break;
                    case 6:
                        scenario[Pick(new[] { "integrator" })] = Pick(new[] { "rk4", "stable-rk4", "euler", "semi-implicit-euler", "heun", "dp54" });
                        break;
                    case 7:
                        scenario["aero"] = new JsonObject
                        {
                            ["drag"] = new JsonObject { ["model"] = Pick(new[] { "stepanek", "goff-carre", "nathan" }) },
                            ["lift"] = new JsonObject { ["model"] = Pick(new[] { "stepanek", "goff-carre", "nathan", "smits-smith-golf" }) },
                        };
                        scenario["spinDecay"] = new JsonObject { ["model"] = "speed-proportional", ["k"] = Number() };
                        break;
                    case 8:
                        scenario["preset"] = Pick(new[] { "tennis", "golf", "soccer", "baseball", "table-tennis", "volleyball", "beach" });
                        break;
                    case 9:
                        raw = "escape";
                        break;
                    case 10:
                        raw = "nest";
                        break;
                    default:
                        raw = "truncate";
                        break;
                }
            }

            KeepShort(scenario);
            string text = root.ToJsonString();
            switch (raw)
            {
                case "escape":
                    // Raw JSON escapes the tree cannot hold: lone surrogates in values and names, a duplicated field, 1e999.
                    string[] hostile = { "\"\\ud800\"", "\"\\udfff\"", "\"a\\ud83c\"", "1e999", "-1e400", "NaN", "\"\\u0000\"" };
                    text = text.Replace("\"drive\"", Pick(hostile)).Replace("\"rk4\"", Pick(hostile));
                    if (_random.Next(2) == 0)
                    {
                        text = text.Replace("{\"name\"", "{\"\\ud800k\":1,\"name\"");
                    }

                    if (_random.Next(2) == 0)
                    {
                        text = text.Replace("\"step\":", "\"step\":0.01,\"step\":");
                    }

                    break;
                case "nest":
                    int depth = 1 + _random.Next(200);
                    text = text.Replace("\"drive\"", new string('[', depth) + new string(']', depth));
                    break;
                case "truncate":
                    text = text.Substring(0, _random.Next(text.Length));
                    break;
            }

            return text;
        }

        // Keep accepted flights short (see MaxStepsKept): maxTime = step x MaxStepsKept when the file asks for more.
        private void KeepShort(JsonObject scenario)
        {
            if (MaxStepsKept <= 0)
            {
                return;
            }

            double step = Read(scenario["step"]) ?? 1.0 / 240;
            double maxTime = Read(scenario["maxTime"]) ?? 10;
            if (step > 0 && maxTime > 0 && maxTime / step > MaxStepsKept && maxTime / step <= 1e7)
            {
                scenario["maxTime"] = step * MaxStepsKept;
            }
        }

        private static double? Read(JsonNode? node)
        {
            try
            {
                return node is JsonValue v && v.TryGetValue(out double d) ? d : null;
            }
            catch (FormatException)
            {
                return null;
            }
        }

        private JsonNode? Value(int depth)
        {
            switch (_random.Next(depth > 2 ? 4 : 9))
            {
                case 0:
                case 1:
                    return Number();
                case 2:
                    return Pick(Strings);
                case 3:
                    return null;
                case 4:
                    return _random.Next(2) == 0;
                case 5:
                    return new JsonArray(Number(), Number(), Number());
                case 6:
                    return new JsonArray(Enumerable.Range(0, _random.Next(6)).Select(_ => Value(depth + 1)).ToArray());
                case 7:
                    return new JsonObject { [Pick(new[] { "model", "cd", "x", "point", "normal" })] = Value(depth + 1) };
                default:
                    return new JsonObject();
            }
        }

        private double Number()
        {
            if (_random.Next(3) == 0)
            {
                // Log-uniform over the whole range of doubles, either sign.
                double magnitude = Math.Pow(10, -320 + _random.NextDouble() * 628);
                return double.IsFinite(magnitude) ? (_random.Next(2) == 0 ? magnitude : -magnitude) : 1;
            }

            return Pick(Numbers);
        }

        private T Pick<T>(IReadOnlyList<T> items) => items[_random.Next(items.Count)];

        private static void Set(JsonObject scenario, string path, JsonNode? value)
        {
            JsonNode node = scenario;
            string[] parts = path.Split('.');
            for (int i = 0; i < parts.Length - 1; i++)
            {
                JsonNode? next = Child(node, parts[i]);
                if (next is not JsonObject)
                {
                    next = new JsonObject();
                    SetChild(node, parts[i], next);
                }

                node = next;
            }

            SetChild(node, parts[^1], value);
        }

        private static JsonNode? Child(JsonNode node, string part)
        {
            if (part.EndsWith("[0]", StringComparison.Ordinal))
            {
                return node[part[..^3]] is JsonArray a && a.Count > 0 ? a[0] : null;
            }

            return node is JsonObject o ? o[part] : null;
        }

        private static void SetChild(JsonNode node, string part, JsonNode? value)
        {
            if (part.EndsWith("[0]", StringComparison.Ordinal))
            {
                string name = part[..^3];
                if (node[name] is JsonArray a && a.Count > 0)
                {
                    a[0] = value;
                }
                else
                {
                    node[name] = new JsonArray(value);
                }

                return;
            }

            node.AsObject()[part] = value;
        }

        /// <summary>The valid file every hostile one starts from: the issue-3 drive.</summary>
        public const string Base = """
            {"scenarios": [{
              "name": "drive",
              "ball": {"mass": 0.057, "radius": 0.033},
              "air": {"density": 1.21, "wind": [0,0,0]},
              "gravity": [0,0,-9.81],
              "aero": {"drag": {"model": "constant", "cd": 0.55}, "lift": {"model": "constant", "cl": 0.175}},
              "spinDecay": {"model": "none"},
              "initial": {"position": [0,0,1], "velocity": [29.7,0,4.2], "angularVelocity": [0,125.7,0]},
              "integrator": "rk4",
              "step": 0.004166666666666667,
              "ground": {"point": [0,0,0], "normal": [0,0,1]},
              "planes": [{"name": "net", "point": [11.885,0,0], "normal": [1,0,0]}],
              "maxTime": 10
            }]}
            """;
    }
}
