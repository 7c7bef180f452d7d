using System;
using System.IO;
using System.Text.Json;
using System.Text.Json.Nodes;

namespace MagnusBall.Cli.Tests
{
    /// <summary>Runs the CLI in-process (no child process) and captures what it prints.</summary>
    internal sealed record CliRun(int ExitCode, string Stdout, string Stderr)
    {
        /// <summary>The issue-3 example scenario (a tennis drive), as a mutable JSON tree.</summary>
        public const string DriveJson = """
            {"scenarios": [{
              "name": "drive",
              "ball": {"mass": 0.057, "radius": 0.033},
              "air": {"density": 1.21, "wind": [0,0,0]},
              "gravity": [0,0,-9.81],
              "aero": {"drag": {"model": "constant", "cd": 0.55},
                       "lift": {"model": "constant", "cl": 0.175}},
              "spinDecay": {"model": "none"},
              "initial": {"position": [0,0,1], "velocity": [29.7,0,4.2], "angularVelocity": [0,125.7,0]},
              "integrator": "rk4",
              "step": 0.004166666666666667,
              "ground": {"point": [0,0,0], "normal": [0,0,1]},
              "planes": [{"name": "net", "point": [11.885,0,0], "normal": [1,0,0]}],
              "maxTime": 10
            }]}
            """;

        public static JsonObject Drive() => JsonNode.Parse(DriveJson)!.AsObject();

        public static JsonObject FirstScenario(JsonObject root) => root["scenarios"]![0]!.AsObject();

        public static CliRun Of(params string[] args)
        {
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            int code = Program.Run(args, stdout, stderr, new StringReader(string.Empty));
            return new CliRun(code, stdout.ToString(), stderr.ToString());
        }

        /// <summary>Runs `simulate -` with <paramref name="json"/> on standard input, plus extra arguments.</summary>
        public static CliRun Simulate(string json, params string[] extra)
        {
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            var args = new string[2 + extra.Length];
            args[0] = "simulate";
            args[1] = "-";
            Array.Copy(extra, 0, args, 2, extra.Length);
            int code = Program.Run(args, stdout, stderr, new StringReader(json));
            return new CliRun(code, stdout.ToString(), stderr.ToString());
        }

        public static CliRun Simulate(JsonNode root, params string[] extra) => Simulate(root.ToJsonString(), extra);

        public JsonElement Json() => JsonDocument.Parse(Stdout).RootElement;

        public JsonElement FirstResult() => Json().GetProperty("results")[0];
    }
}
