using System;
using System.Linq;
using System.Text.Json;
using System.Text.Json.Nodes;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests.Api
{
    /// <summary>`magnusball aim`: the four solves, "unreachable" as a result, and bad aim files.</summary>
    [TestFixture]
    public class AimTests
    {
        // A tennis shot from 1 m at 30 m/s with the thesis's constant coefficients.
        private const string Common = """
            "ball": {"mass": 0.057, "radius": 0.033}, "air": {"density": 1.21}, "gravity": [0, 0, -9.81],
            "aero": {"drag": {"model": "constant", "cd": 0.55}, "lift": {"model": "constant", "cl": 0.175}},
            "integrator": "rk4", "step": 0.004166666666666667, "maxTime": 5,
            "launch": {"position": [0, 0, 1], "spin": {"topspin": 125.66}}
            """;

        private static JsonObject Aim(string find) =>
            JsonNode.Parse("{\"aims\": [{\"name\": \"a\", " + Common + ", \"find\": " + find + "}]}")!.AsObject();

        private static CliRun Run(JsonNode root)
        {
            var stdout = new System.IO.StringWriter();
            var stderr = new System.IO.StringWriter();
            int code = Program.Run(new[] { "aim", "-" }, stdout, stderr, new System.IO.StringReader(root.ToJsonString()));
            return new CliRun(code, stdout.ToString(), stderr.ToString());
        }

        private static JsonElement Solve(string find)
        {
            CliRun run = Run(Aim(find));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            return run.FirstResult();
        }

        private static double[] Vec(JsonElement e) => e.EnumerateArray().Select(x => x.GetDouble()).ToArray();

        /// <summary>Flies the solved launch with `simulate` and returns its first result.</summary>
        private static JsonElement Fly(JsonElement solution, string planes)
        {
            string json = "{\"scenarios\": [{" + Common.Replace("\"launch\": {\"position\": [0, 0, 1], \"spin\": {\"topspin\": 125.66}}", "") +
                          "\"initial\": {\"position\": [0, 0, 1], \"velocity\": " + solution.GetProperty("velocity").GetRawText() +
                          ", \"angularVelocity\": " + solution.GetProperty("angularVelocity").GetRawText() + "}, \"planes\": " + planes + "}]}";
            CliRun run = CliRun.Simulate(json);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            return run.FirstResult();
        }

        [TestCase("euler")]
        [TestCase("rk4")]
        public void StepBeyondTheStabilityBound_IsRefused_NotAnsweredUnreachable(string integrator)
        {
            // A table-tennis ball (2.7 g, 20 mm, C_D 0.55, no spin) at 100 m/s at a 0.1 s step: beyond both methods'
            // bounds (about 0.06 and 0.08 s here). The trials would fly a wrong path and the solve print "unreachable" with exit 0.
            JsonObject root = Aim("""{"kind": "elevation-to-reach", "speed": 100, "target": [20, 0, 0]}""");
            JsonObject a = root["aims"]![0]!.AsObject();
            a["ball"] = new JsonObject { ["mass"] = 0.0027, ["radius"] = 0.02 };
            a["launch"] = new JsonObject { ["position"] = new JsonArray(0, 0, 1) }; // no spin: drag alone
            a["integrator"] = integrator;
            a["step"] = 0.1;
            CliRun run = Run(root);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.Stdout);
            Assert.That(run.Stderr, Does.StartWith($"magnusball: aims[0].step: a step of 0.1 s is beyond {integrator}'s stability bound"));

            // stable-rk4 splits the step and solves the same request.
            a["integrator"] = "stable-rk4";
            CliRun stable = Run(root);
            Assert.That(stable.ExitCode, Is.EqualTo(0), stable.Stderr);
            Assert.That(stable.FirstResult().GetProperty("status").GetString(), Is.EqualTo("solved"));
        }

        [Test]
        public void StabilityCheck_TakesTheLaunchIntoTheWind()
        {
            // A 2.7 g, 20 mm ball (C_D 0.55, no spin) at 50 m/s, Euler at 0.1 s: h sigma = 0.1 x 1.1 x 2 k (s + g h) C_D is
            // 1.74 in still air, within Euler's 2, and 2.76 into a 30 m/s wind, beyond it: the check takes the launch
            // the request can make with the largest air speed, whichever way the wind blows.
            JsonObject root = Aim("""{"kind": "elevation-to-reach", "speed": 50, "target": [20, 0, 0]}""");
            JsonObject a = root["aims"]![0]!.AsObject();
            a["ball"] = new JsonObject { ["mass"] = 0.0027, ["radius"] = 0.02 };
            a["aero"] = new JsonObject { ["drag"] = new JsonObject { ["model"] = "constant", ["cd"] = 0.55 } };
            a["launch"] = new JsonObject { ["position"] = new JsonArray(0, 0, 1) };
            a["integrator"] = "euler";
            a["step"] = 0.1;
            CliRun still = Run(root);
            Assert.That(still.ExitCode, Is.EqualTo(0), still.Stderr);

            a["air"] = new JsonObject { ["density"] = 1.21, ["wind"] = new JsonArray(0, 30, 0) }; // a crosswind
            CliRun windy = Run(root);
            Assert.That(windy.ExitCode, Is.EqualTo(2), windy.Stdout);
            Assert.That(windy.Stderr, Does.StartWith("magnusball: aims[0].step: a step of 0.1 s is beyond euler's stability bound"));
        }

        [Test]
        public void MinimumElevationToClear_TouchesTheTape()
        {
            JsonElement s = Solve("""{"kind": "minimum-elevation-to-clear", "speed": 30, "plane": {"point": [11.885, 0, 0], "normal": [1, 0, 0]}, "height": 0.914}""");
            Assert.That(s.GetProperty("status").GetString(), Is.EqualTo("solved"));
            // Thesis constants and 20 rev/s topspin: the thesis reports 6.3 deg; issue 3 allows 0.2 deg.
            Assert.That(s.GetProperty("elevationDegrees").GetDouble(), Is.EqualTo(6.3).Within(0.2));
            JsonElement flown = Fly(s, """[{"name": "net", "point": [11.885, 0, 0], "normal": [1, 0, 0]}]""");
            // The solver refines to 1e-8 rad (1.2e-7 m at the net); the CLI replays the same flight.
            Assert.That(Vec(flown.GetProperty("crossings")[0].GetProperty("position"))[2], Is.EqualTo(0.914).Within(1e-6));
        }

        [Test]
        public void ElevationToReach_LandsOnTheTarget()
        {
            JsonElement s = Solve("""{"kind": "elevation-to-reach", "speed": 30, "target": [23.77, 0, 0]}""");
            // The thesis's 12.8 deg (baseline, topspin), within issue 3's 0.2 deg.
            Assert.That(s.GetProperty("elevationDegrees").GetDouble(), Is.EqualTo(12.8).Within(0.2));
            Assert.That(s.GetProperty("miss").GetDouble(), Is.LessThan(1e-6));
            JsonElement flown = Fly(s, "[]");
            // Same 1e-8 rad refinement: 2e-7 m at 23.8 m.
            Assert.That(Vec(flown.GetProperty("landing").GetProperty("position"))[0], Is.EqualTo(23.77).Within(1e-6));
        }

        [Test]
        public void AnglesToReach_CorrectsACurvingBall()
        {
            string json = Aim("""{"kind": "angles-to-reach", "speed": 30, "target": [20, 2, 0.5]}""").ToJsonString()
                .Replace("\"topspin\":125.66", "\"sidespin\":100");
            CliRun run = Run(JsonNode.Parse(json)!);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement s = run.FirstResult();
            Assert.That(s.GetProperty("status").GetString(), Is.EqualTo("solved"));
            Assert.That(Math.Abs(s.GetProperty("azimuthDegrees").GetDouble()), Is.GreaterThan(0.1), "a curving ball is aimed off the target line");
            double[] arrival = Vec(s.GetProperty("arrival").GetProperty("position"));
            // The solver's miss is reported and below its refinement (1e-8 rad at 20 m = 2e-7 m).
            Assert.That(arrival[1], Is.EqualTo(2).Within(1e-5));
            Assert.That(arrival[2], Is.EqualTo(0.5).Within(1e-5));
        }

        [Test]
        public void SpeedToReach_FindsTheSpeed()
        {
            JsonElement s = Solve("""{"kind": "speed-to-reach", "elevationDegrees": 10, "target": [20, 0, 0]}""");
            Assert.That(s.GetProperty("status").GetString(), Is.EqualTo("solved"));
            double speed = s.GetProperty("speed").GetDouble();
            Assert.That(speed, Is.GreaterThan(10).And.LessThan(40));
            JsonElement flown = Fly(s, "[]");
            // Speed refined to 1e-8 m/s; the landing moves ~1 m per m/s here, so 1e-6 m is loose.
            Assert.That(Vec(flown.GetProperty("landing").GetProperty("position"))[0], Is.EqualTo(20).Within(1e-6));
        }

        [Test]
        public void OutOfReach_IsUnreachable_NotAnError()
        {
            JsonElement s = Solve("""{"kind": "elevation-to-reach", "speed": 5, "target": [60, 0, 0]}""");
            Assert.That(s.GetProperty("status").GetString(), Is.EqualTo("unreachable"));
            Assert.That(s.TryGetProperty("elevationDegrees", out _), Is.False);
            Assert.That(s.GetProperty("simulations").GetInt32(), Is.GreaterThan(0));
        }

        [TestCase("""{"speed": 30, "target": [20, 0, 0]}""", "aims[0].find.kind: required field is missing", TestName = "BadAim_MissingKind")]
        [TestCase("""{"kind": "lob", "speed": 30}""", "aims[0].find.kind: unknown kind 'lob'; expected one of: minimum-elevation-to-clear, elevation-to-reach, angles-to-reach, speed-to-reach", TestName = "BadAim_UnknownKind")]
        [TestCase("""{"kind": "elevation-to-reach", "target": [20, 0, 0]}""", "aims[0].find.speed: required field is missing", TestName = "BadAim_MissingSpeed")]
        [TestCase("""{"kind": "elevation-to-reach", "speed": -3, "target": [20, 0, 0]}""", "aims[0].find.speed: must be finite and > 0; got -3", TestName = "BadAim_NegativeSpeed")]
        [TestCase("""{"kind": "elevation-to-reach", "speed": 30, "target": [20, 0]}""", "aims[0].find.target: must be an array of 3 finite numbers", TestName = "BadAim_ShortTarget")]
        [TestCase("""{"kind": "elevation-to-reach", "speed": 30, "target": [20, 0, 0], "height": 1}""", "aims[0].find.height: unknown field", TestName = "BadAim_FieldOfAnotherKind")]
        [TestCase("""{"kind": "speed-to-reach", "elevationDegrees": 95, "target": [20, 0, 0]}""", "aims[0].find.elevationDegrees: must be in [-89.999, 89.999]; got 95", TestName = "BadAim_ElevationOutOfRange")]
        [TestCase("""{"kind": "minimum-elevation-to-clear", "speed": 30, "plane": {"point": [11.885, 0, 0]}, "height": 0.914}""", "aims[0].find.plane.normal: required field is missing", TestName = "BadAim_PlaneWithoutNormal")]
        [TestCase("""{"kind": "minimum-elevation-to-clear", "speed": 30, "plane": {"point": [11.885, 0, 0], "normal": [0, 0, 1]}, "height": 0.914}""", "aims[0].find: plane must not be horizontal", TestName = "BadAim_HorizontalPlane")]
        [TestCase("""{"kind": "elevation-to-reach", "speed": 30, "target": [0, 0, 5]}""", "aims[0].find: ", TestName = "BadAim_TargetStraightAbove")]
        public void BadAim_ExitsWithTwo_AndNamesTheField(string find, string expected)
        {
            CliRun run = Run(Aim(find));
            Assert.Multiple(() =>
            {
                Assert.That(run.ExitCode, Is.EqualTo(2), run.Stderr);
                Assert.That(run.Stderr, Does.StartWith("magnusball: " + expected));
                Assert.That(run.Stdout, Is.Empty);
            });
        }

        [Test]
        public void BadAim_NoGround_IsAnError()
        {
            JsonObject root = Aim("""{"kind": "elevation-to-reach", "speed": 30, "target": [20, 0, 0]}""");
            root["aims"]![0]!["ground"] = null;
            CliRun run = Run(root);
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr, Does.StartWith("magnusball: aims[0].ground: must not be null for aiming"));
        }

        [Test]
        public void BadAim_ZeroGravity_IsAnError()
        {
            JsonObject root = Aim("""{"kind": "elevation-to-reach", "speed": 30, "target": [20, 0, 0]}""");
            root["aims"]![0]!["gravity"] = new JsonArray(0, 0, 0);
            CliRun run = Run(root);
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr, Does.StartWith("magnusball: aims[0].gravity: must not be zero for aiming"));
        }

        [Test]
        public void BadAim_TypoInLaunch_IsAnError()
        {
            JsonObject root = Aim("""{"kind": "elevation-to-reach", "speed": 30, "target": [20, 0, 0]}""");
            root["aims"]![0]!["launch"]!["spin"]!["topSpin"] = 3;
            CliRun run = Run(root);
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr, Does.StartWith("magnusball: aims[0].launch.spin.topSpin: unknown field; expected one of: gyro, sidespin, topspin"));
        }

        [Test]
        public void BadAim_MissingAims_IsAnError()
        {
            CliRun run = Run(JsonNode.Parse("{\"scenarios\": []}")!);
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr, Does.StartWith("magnusball: aims: required field is missing"));
        }

        // A tennis ball (the thesis's constant coefficients) from just before the net to a target low beyond it, elevations
        // capped at 5 degrees: every launch that reaches the target meets the net (as AimShapesTests in the library's tests).
        private static JsonObject LowOverTheNet(bool withNet, string extraFind = "")
        {
            string shapes = withNet ? """, "shapes": [{"type": "tennis-net", "firstId": 0, "centreOnGround": [11.885, 0, 0], "across": [0, 1, 0]}]""" : "";
            return JsonNode.Parse("""
                {"aims": [{"name": "low", "ball": {"mass": 0.057, "radius": 0.033}, "air": {"density": 1.21}, "gravity": [0, 0, -9.81],
                  "aero": {"drag": {"model": "constant", "cd": 0.55}},
                  "integrator": "rk4", "step": 0.004166666666666667, "maxTime": 5,
                  "launch": {"position": [9, 0, 0.5]}, "limits": {"maximumElevationDegrees": 5}
                """ + shapes + """, "find": {"kind": "elevation-to-reach", "speed": 20, "target": [13, 0, 0.3]""" + extraFind + "}}]}")!.AsObject();
        }

        [Test]
        public void Shapes_AreObstacles_AShotTheNetStopsIsBlocked()
        {
            CliRun free = Run(LowOverTheNet(withNet: false));
            Assert.That(free.ExitCode, Is.EqualTo(0), free.Stderr);
            Assert.That(free.FirstResult().GetProperty("status").GetString(), Is.EqualTo("solved"), "without the net it is reached");
            CliRun blocked = Run(LowOverTheNet(withNet: true));
            Assert.That(blocked.ExitCode, Is.EqualTo(0), blocked.Stderr);
            Assert.That(blocked.FirstResult().GetProperty("status").GetString(), Is.EqualTo("blocked"));
        }

        [Test]
        public void ABankShot_ViaTheBackboard_IsSolved_AndAnUnknownShapeIdIsRefused()
        {
            // A basketball from 2.2 m, 5 m in front of the board's foot, at 9 m/s: off the backboard (id 11) to the rim's
            // centre (the hoop's ring, id 10, as SportShapes places it).
            var rim = (MagnusBall.Contact.Shapes.TorusShape)MagnusBall.Shots.SportShapes.BasketballHoop(
                10, new MagnusBall.Vector3d(5, 0, 0), -MagnusBall.Vector3d.UnitX, MagnusBall.Vector3d.UnitZ)[0];
            string target = string.Format(System.Globalization.CultureInfo.InvariantCulture, "[{0:R}, {1:R}, {2:R}]", rim.Centre.X, rim.Centre.Y, rim.Centre.Z);
            string hoop = """[{"type": "basketball-hoop", "firstId": 10, "boardFootOnGround": [5, 0, 0], "towardCourt": [-1, 0, 0]}]""";
            JsonObject root = JsonNode.Parse("""
                {"aims": [{"name": "bank", "preset": "basketball", "integrator": "rk4", "step": 0.004166666666666667, "maxTime": 5,
                  "shapes": 
                """ + hoop + """
                , "launch": {"position": [0, 0, 2.2]},
                  "find": {"kind": "elevation-to-reach", "speed": 9, "target": 
                """ + target + """
                , "viaShapeId": 11}}]}
                """)!.AsObject();
            CliRun run = Run(root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement r = run.FirstResult();
            Assert.That(r.GetProperty("status").GetString(), Is.EqualTo("solved"), run.Stdout);
            Assert.That(Vec(r.GetProperty("arrival").GetProperty("velocity"))[0], Is.LessThan(0), "coming back off the board");

            root["aims"]![0]!["find"]!["viaShapeId"] = 12;
            CliRun refused = Run(root);
            Assert.That(refused.ExitCode, Is.EqualTo(2));
            Assert.That(refused.Stderr, Does.Contain("aims[0].find.viaShapeId: must be the id of one of the aim's shapes (the aim's shape ids are 10, 11); got 12"));
        }
    }
}
