using System;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Xml.Linq;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests
{
    /// <summary>`magnusball simulate`: the output contract, event accuracy, defaults, frames, CSV and SVG.</summary>
    [TestFixture]
    public class SimulateTests
    {
        private static double[] Vec(JsonElement e) => e.EnumerateArray().Select(x => x.GetDouble()).ToArray();

        private static JsonObject S(JsonObject root) => CliRun.FirstScenario(root);

        [Test]
        public void IssueExample_WithItsComments_ParsesAsWritten()
        {
            // The annotated example of issue 3, comments included: the format is the contract.
            string json = """
                {"scenarios": [{
                  "name": "drive",
                  "ball": {"mass": 0.057, "radius": 0.033},
                  "air": {"density": 1.21, "wind": [0,0,0]},
                  "gravity": [0,0,-9.81],
                  "aero": {"drag": {"model": "constant", "cd": 0.55},            // models: none | constant {cd} | stepanek
                           "lift": {"model": "constant", "cl": 0.175}},          // models: none | constant {cl} | stepanek | linear-spin {k}
                  "spinDecay": {"model": "none"},                                // or {"model": "exponential", "tau": 2.5}
                  "initial": {"position": [0,0,1], "velocity": [29.7,0,4.2], "angularVelocity": [0,125.7,0]},
                  "integrator": "rk4",                                           // euler | semi-implicit-euler | heun | rk4 (+ any you add)
                  "step": 0.004166666666666667,
                  "ground": {"point": [0,0,0], "normal": [0,0,1]},
                  "planes": [{"name": "net", "point": [11.885,0,0], "normal": [1,0,0]}],
                  "maxTime": 10
                }]}
                """;
            CliRun run = CliRun.Simulate(json);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            Assert.That(run.Stdout, Is.EqualTo(CliRun.Simulate(CliRun.DriveJson).Stdout));
        }

        [Test]
        public void LaunchedLevelFromTheGround_LandsAtOnce()
        {
            // The ball's centre starts exactly on the ground plane moving level: gravity takes it into the ground
            // at once, so it lands at t = 0 (before: "landing": null and a flight under the ground to maxTime).
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["position"] = new JsonArray(0, 0, 0);
            S(root)["initial"]!["velocity"] = new JsonArray(5, 0, 0);
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement r = run.FirstResult();
            Assert.That(r.GetProperty("landing").ValueKind, Is.EqualTo(JsonValueKind.Object));
            Assert.That(r.GetProperty("landing").GetProperty("time").GetDouble(), Is.EqualTo(0));
            Assert.That(Vec(r.GetProperty("landing").GetProperty("position")), Is.EqualTo(new double[] { 0, 0, 0 }));
            Assert.That(r.GetProperty("steps").GetInt32(), Is.EqualTo(1));
        }

        [Test]
        public void Output_HasTheContractShape_AndEventsLieOnTheirSurfaces()
        {
            CliRun run = CliRun.Simulate(CliRun.DriveJson);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement r = run.FirstResult();
            double[] landing = Vec(r.GetProperty("landing").GetProperty("position"));
            double[] landingVelocity = Vec(r.GetProperty("landing").GetProperty("velocity"));
            double[] apex = Vec(r.GetProperty("apex").GetProperty("position"));
            JsonElement net = r.GetProperty("crossings")[0];
            int steps = r.GetProperty("steps").GetInt32();
            double landingTime = r.GetProperty("landing").GetProperty("time").GetDouble();
            Assert.Multiple(() =>
            {
                Assert.That(r.GetProperty("name").GetString(), Is.EqualTo("drive"));
                Assert.That(landing, Has.Length.EqualTo(3));
                // The root is found to 1e-12 s; at a 6 m/s descent that is 6e-12 m off the plane.
                Assert.That(landing[2], Is.EqualTo(0).Within(1e-9));
                Assert.That(landingVelocity[2], Is.LessThan(0), "lands moving down");
                Assert.That(apex[2], Is.GreaterThan(1.0));
                Assert.That(r.GetProperty("crossings").GetArrayLength(), Is.EqualTo(1));
                Assert.That(net.GetProperty("name").GetString(), Is.EqualTo("net"));
                // Same root tolerance: 1e-12 s at 25 m/s.
                Assert.That(Vec(net.GetProperty("position"))[0], Is.EqualTo(11.885).Within(1e-9));
                Assert.That(net.TryGetProperty("inside", out _), Is.False, "an unbounded plane has no 'inside'");
                Assert.That(steps, Is.EqualTo((int)Math.Ceiling(landingTime / (1.0 / 240))));
                // One evaluation for the launch derivative, then four per RK4 step (the last is the next step's k1).
                Assert.That(r.GetProperty("derivativeEvaluations").GetInt64(), Is.EqualTo(1 + 4L * steps));
            });
        }

        [TestCase(1.0 / 60, 1e-5, TestName = "Landing_Rk4At60Hz_IsWithin1e-5mOfTheReference")]
        [TestCase(1.0 / 240, 1e-6, TestName = "Landing_Rk4At240Hz_IsWithin1e-6mOfTheReference")]
        public void Landing_KeepsTheIntegratorsOrder(double step, double tolerance)
        {
            // Tolerances are issue 3's: a 24 m drive's landing within 1e-5 m (1/60 s) and 1e-6 m (1/240 s).
            // Reference: the same flight at 1e-4 s, whose RK4 error is ~(1e-4 / (1/240))^4 = 3e-7 of the 1/240 s error.
            JsonObject root = CliRun.Drive();
            S(root)["step"] = step;
            JsonObject reference = CliRun.Drive();
            S(reference)["step"] = 1e-4;
            double[] p = Vec(CliRun.Simulate(root).FirstResult().GetProperty("landing").GetProperty("position"));
            double[] q = Vec(CliRun.Simulate(reference).FirstResult().GetProperty("landing").GetProperty("position"));
            double error = Math.Sqrt(p.Zip(q, (a, b) => (a - b) * (a - b)).Sum());
            TestContext.Out.WriteLine($"step {step:R} s: landing {p[0]:F9} m, reference {q[0]:F9} m, error {error:E2} m");
            Assert.That(error, Is.LessThan(tolerance));
        }

        [Test]
        public void LandingIsNotTheFirstStepBelowGround()
        {
            // With a 1/30 s step the first step below ground is ~0.2 m past the interpolated landing.
            JsonObject root = CliRun.Drive();
            S(root)["step"] = 1.0 / 30;
            JsonElement r = CliRun.Simulate(root).FirstResult();
            double t = r.GetProperty("landing").GetProperty("time").GetDouble();
            Assert.That(t % (1.0 / 30), Is.GreaterThan(1e-3), "the landing time falls inside a step, not on its end");
        }

        [Test]
        public void Defaults_AreDocumented_Values()
        {
            // Omitted: air (1.225 kg/m^3, no wind), gravity ([0,0,-9.80665]), ground (through the origin, normal up),
            // integrator (rk4), step (1/240 s), maxTime (10 s), spinDecay (none), name ("scenario-0").
            JsonObject bare = CliRun.Drive();
            foreach (string field in new[] { "air", "gravity", "ground", "integrator", "step", "maxTime", "spinDecay", "name", "planes" })
            {
                S(bare).Remove(field);
            }

            JsonObject explicitDefaults = CliRun.Drive();
            JsonObject e = S(explicitDefaults);
            e["name"] = "scenario-0";
            e["air"] = JsonNode.Parse("{\"density\": 1.225, \"wind\": [0, 0, 0]}");
            e["gravity"] = JsonNode.Parse("[0, 0, -9.80665]");
            e["ground"] = JsonNode.Parse("{\"point\": [0, 0, 0], \"normal\": [0, 0, 1]}");
            e["integrator"] = "rk4";
            e["step"] = 1.0 / 240;
            e["maxTime"] = 10;
            e["spinDecay"] = JsonNode.Parse("{\"model\": \"none\"}");
            e.Remove("planes");

            CliRun a = CliRun.Simulate(bare);
            CliRun b = CliRun.Simulate(explicitDefaults);
            Assert.That(a.ExitCode, Is.EqualTo(0), a.Stderr);
            Assert.That(a.Stdout, Is.EqualTo(b.Stdout));
            Assert.That(a.FirstResult().GetProperty("landing").ValueKind, Is.EqualTo(JsonValueKind.Object));
        }

        [Test]
        public void MissingAero_IsAVacuumFlight()
        {
            JsonObject root = CliRun.Drive();
            S(root).Remove("aero");
            S(root)["planes"] = new JsonArray();
            JsonElement r = CliRun.Simulate(root).FirstResult();
            // Vacuum apex height: z0 + vz^2 / 2g = 1 + 4.2^2 / 19.62; RK4 is exact for a parabola up to rounding.
            Assert.That(Vec(r.GetProperty("apex").GetProperty("position"))[2], Is.EqualTo(1 + 4.2 * 4.2 / (2 * 9.81)).Within(1e-9));
        }

        [Test]
        public void GroundNull_FliesToMaxTime_WithoutLanding()
        {
            JsonObject root = CliRun.Drive();
            S(root)["ground"] = null;
            S(root)["maxTime"] = 2;
            JsonElement r = CliRun.Simulate(root).FirstResult();
            Assert.That(r.GetProperty("landing").ValueKind, Is.EqualTo(JsonValueKind.Null));
            Assert.That(r.GetProperty("steps").GetInt32(), Is.EqualTo(480));
        }

        [Test]
        public void FallingFromTheStart_HasNoApex()
        {
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["velocity"] = new JsonArray(29.7, 0, -1);
            JsonElement r = CliRun.Simulate(root).FirstResult();
            Assert.That(r.GetProperty("apex").ValueKind, Is.EqualTo(JsonValueKind.Null));
        }

        [Test]
        public void PlaneCrossedAgainstItsNormal_DoesNotCount()
        {
            JsonObject root = CliRun.Drive();
            S(root)["planes"]![0]!["normal"] = new JsonArray(-1, 0, 0);
            JsonElement r = CliRun.Simulate(root).FirstResult();
            Assert.That(r.GetProperty("crossings").GetArrayLength(), Is.EqualTo(0));
        }

        [Test]
        public void PlaneBeyondTheLanding_IsNotCrossed()
        {
            JsonObject root = CliRun.Drive();
            S(root)["planes"]![0]!["point"] = new JsonArray(30, 0, 0);
            JsonElement r = CliRun.Simulate(root).FirstResult();
            Assert.That(r.GetProperty("crossings").GetArrayLength(), Is.EqualTo(0));
        }

        [TestCase(0.914, false, TestName = "BoundedNet_BallAboveTheTape_IsNotInside")]
        [TestCase(2.0, true, TestName = "BoundedNet_TallNet_IsInside")]
        public void BoundedPlane_ReportsInside(double netHeight, bool inside)
        {
            JsonObject root = CliRun.Drive();
            S(root)["planes"]![0]!["bounds"] = new JsonObject { ["height"] = new JsonArray(0, netHeight), ["width"] = new JsonArray(-6.4, 6.4) };
            JsonElement crossing = CliRun.Simulate(root).FirstResult().GetProperty("crossings")[0];
            Assert.That(crossing.GetProperty("inside").GetBoolean(), Is.EqualTo(inside));
        }

        [Test]
        public void CrossingsOfSeveralPlanes_AreInTimeOrder()
        {
            JsonObject root = CliRun.Drive();
            var planes = S(root)["planes"]!.AsArray();
            planes.Insert(0, JsonNode.Parse("{\"name\": \"far\", \"point\": [15, 0, 0], \"normal\": [1, 0, 0]}"));
            planes.Add(JsonNode.Parse("{\"name\": \"near\", \"point\": [5, 0, 0], \"normal\": [1, 0, 0]}"));
            JsonElement crossings = CliRun.Simulate(root).FirstResult().GetProperty("crossings");
            Assert.That(crossings.EnumerateArray().Select(c => c.GetProperty("name").GetString()), Is.EqualTo(new[] { "near", "net", "far" }));
        }

        [Test]
        public void YUpFrame_GivesTheSameFlight()
        {
            // Rotate the whole scenario by -90 deg about x: (x, y, z) -> (x, z, -y). Spin rotates the same way.
            JsonObject root = CliRun.Drive();
            JsonObject s = S(root);
            s["gravity"] = new JsonArray(0, -9.81, 0);
            s["initial"]!["position"] = new JsonArray(0, 1, 0);
            s["initial"]!["velocity"] = new JsonArray(29.7, 4.2, 0);
            s["initial"]!["angularVelocity"] = new JsonArray(0, 0, -125.7);
            s["ground"]!["normal"] = new JsonArray(0, 1, 0);
            JsonElement z = CliRun.Simulate(CliRun.Drive()).FirstResult();
            JsonElement y = CliRun.Simulate(root).FirstResult();
            double[] pz = Vec(z.GetProperty("landing").GetProperty("position"));
            double[] py = Vec(y.GetProperty("landing").GetProperty("position"));
            // Only rounding differs between frames (components are permuted, not mixed).
            Assert.That(py[0], Is.EqualTo(pz[0]).Within(1e-9));
            Assert.That(py[1], Is.EqualTo(pz[2]).Within(1e-9));
            Assert.That(py[2], Is.EqualTo(-pz[1]).Within(1e-9));
            Assert.That(y.GetProperty("landing").GetProperty("time").GetDouble(), Is.EqualTo(z.GetProperty("landing").GetProperty("time").GetDouble()).Within(1e-12));
        }

        [Test]
        public void SeveralScenarios_GiveResultsInOrder()
        {
            JsonObject root = CliRun.Drive();
            JsonObject second = (JsonObject)S(root).DeepClone();
            second["name"] = "lob";
            second["initial"]!["velocity"] = new JsonArray(15, 0, 12);
            root["scenarios"]!.AsArray().Add(second);
            JsonElement results = CliRun.Simulate(root).Json().GetProperty("results");
            Assert.That(results.EnumerateArray().Select(r => r.GetProperty("name").GetString()), Is.EqualTo(new[] { "drive", "lob" }));
        }

        [TestCase("euler", 1)]
        [TestCase("semi-implicit-euler", 1)]
        [TestCase("heun", 2)]
        [TestCase("RK4", 4)]
        public void EveryIntegrator_RunsAndCountsItsEvaluations(string name, int perStep)
        {
            JsonObject root = CliRun.Drive();
            S(root)["integrator"] = name;
            JsonElement r = CliRun.Simulate(root).FirstResult();
            int steps = r.GetProperty("steps").GetInt32();
            Assert.That(r.GetProperty("derivativeEvaluations").GetInt64(), Is.EqualTo(1 + (long)perStep * steps));
            // Wiring, not accuracy (the library's convergence tests measure that): the named method flies the drive
            // to land near RK4's 18.67 m; measured at 1/240 s: semi-implicit Euler 18.55 m, the others closer. 0.5 m
            // would catch a wrong method or a broken step, not an O(h) error.
            Assert.That(Vec(r.GetProperty("landing").GetProperty("position"))[0], Is.EqualTo(18.67).Within(0.5));
        }

        [Test]
        public void Csv_ListsTheStepsAndEndsAtTheLanding()
        {
            CliRun run = CliRun.Simulate(CliRun.DriveJson, "--csv");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            string[] lines = run.Stdout.TrimEnd('\n').Split('\n');
            JsonElement r = CliRun.Simulate(CliRun.DriveJson).FirstResult();
            int steps = r.GetProperty("steps").GetInt32();
            double landingTime = r.GetProperty("landing").GetProperty("time").GetDouble();
            string[] last = lines[^1].Split(',');
            Assert.Multiple(() =>
            {
                Assert.That(lines[0], Is.EqualTo("scenario,time,x,y,z,vx,vy,vz,wx,wy,wz"));
                Assert.That(lines[1], Is.EqualTo("drive,0,0,0,1,29.7,0,4.2,0,125.7,0"));
                // Launch, steps - 1 full steps above ground, then the landing: steps + 1 rows after the header.
                Assert.That(lines, Has.Length.EqualTo(steps + 2));
                Assert.That(double.Parse(last[1], System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(landingTime));
            });
        }

        [Test]
        public void Samples_AreEvenlySpaced_InCsvAndJson()
        {
            CliRun csv = CliRun.Simulate(CliRun.DriveJson, "--csv", "--samples", "11");
            string[] lines = csv.Stdout.TrimEnd('\n').Split('\n');
            Assert.That(lines, Has.Length.EqualTo(12));

            JsonElement r = CliRun.Simulate(CliRun.DriveJson, "--samples", "11").FirstResult();
            JsonElement samples = r.GetProperty("samples");
            double landingTime = r.GetProperty("landing").GetProperty("time").GetDouble();
            Assert.That(samples.GetArrayLength(), Is.EqualTo(11));
            for (int i = 0; i < 11; i++)
            {
                Assert.That(samples[i].GetProperty("time").GetDouble(), Is.EqualTo(landingTime * i / 10).Within(1e-12));
            }

            Assert.That(Vec(samples[10].GetProperty("position")), Is.EqualTo(Vec(r.GetProperty("landing").GetProperty("position"))));
            Assert.That(Vec(samples[0].GetProperty("position")), Is.EqualTo(new[] { 0.0, 0.0, 1.0 }));
        }

        [Test]
        public void Json_IsValid_AndKeepsNamesExactly()
        {
            JsonObject root = CliRun.Drive();
            S(root)["name"] = "drive \"flat\" \\ \u00e9\u00e8 \n <&>";
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.FirstResult().GetProperty("name").GetString(), Is.EqualTo("drive \"flat\" \\ \u00e9\u00e8 \n <&>"));
            Assert.That(run.Stdout, Does.Contain("\"position\": [0, 0, 1]").Or.Contain("\"position\": [11.885, 0,"), "vectors on one line");
            Assert.That(run.Stdout, Does.EndWith("}\n"));
        }

        [Test]
        public void CsvQuotesNamesWithCommas()
        {
            JsonObject root = CliRun.Drive();
            S(root)["name"] = "drive, \"flat\"";
            string[] lines = CliRun.Simulate(root, "--csv", "--samples", "2").Stdout.Split('\n');
            Assert.That(lines[1], Does.StartWith("\"drive, \"\"flat\"\"\",0,"));
        }

        [TestCase("side", 1)]
        [TestCase("top", 1)]
        [TestCase("both", 2)]
        public void SvgView_ChoosesTheViews(string view, int views)
        {
            string path = Path.Combine(Path.GetTempPath(), $"magnusball-{Guid.NewGuid():N}.svg");
            try
            {
                CliRun run = CliRun.Simulate(CliRun.DriveJson, "--svg", path, "--svg-view", view);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
                XNamespace ns = "http://www.w3.org/2000/svg";
                XDocument svg = XDocument.Load(path);
                Assert.That(svg.Descendants(ns + "polyline").Count(), Is.EqualTo(views));
                Assert.That(svg.Descendants(ns + "text").Count(t => t.Value.EndsWith(" view")), Is.EqualTo(views));
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Test]
        public void SvgView_WithoutSvg_IsAUsageError()
        {
            CliRun run = CliRun.Simulate(CliRun.DriveJson, "--svg-view", "top");
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr, Does.Contain("--svg-view needs --svg"));
            Assert.That(run.Stdout, Is.Empty);
        }

        [Test]
        public void AnOptionGivenTwice_IsAUsageError()
        {
            // The last one won silently (a new user's report), where a repeated JSON field is an error.
            foreach (string[] options in new[] { new[] { "--samples", "5", "--samples", "10" }, new[] { "--csv", "--csv" } })
            {
                CliRun run = CliRun.Simulate(CliRun.DriveJson, options);
                Assert.That(run.ExitCode, Is.EqualTo(2), string.Join(" ", options));
                Assert.That(run.Stderr, Does.Contain(options[0] + " is given twice"));
                Assert.That(run.Stdout, Is.Empty);
            }
        }

        [Test]
        public void Svg_ThatCannotBeWritten_SaysItIsTheSvgFile()
        {
            string path = Path.Combine(Path.GetTempPath(), $"magnusball-missing-{Guid.NewGuid():N}", "x.svg");
            CliRun run = CliRun.Simulate(CliRun.DriveJson, "--svg", path);
            Assert.That(run.ExitCode, Is.EqualTo(1));
            Assert.That(run.Stderr, Does.Contain("cannot write the --svg file '" + path + "'"));
            Assert.That(run.Stdout, Is.Empty, "nothing printed when the picture asked for is not written");
        }

        [Test]
        public void Svg_DrawsBothViewsOfEveryFlight_AndThePlanes()
        {
            JsonObject root = CliRun.Drive();
            JsonObject second = (JsonObject)S(root).DeepClone();
            second["name"] = "lob <&>";
            second["initial"]!["velocity"] = new JsonArray(15, 0, 12);
            root["scenarios"]!.AsArray().Add(second);
            string path = Path.Combine(Path.GetTempPath(), $"magnusball-{Guid.NewGuid():N}.svg");
            try
            {
                CliRun run = CliRun.Simulate(root, "--svg", path);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
                XDocument svg = XDocument.Load(path); // well-formed XML, names escaped
                XNamespace ns = "http://www.w3.org/2000/svg";
                Assert.That(svg.Root!.Name, Is.EqualTo(ns + "svg"));
                Assert.That(svg.Descendants(ns + "polyline").Count(), Is.EqualTo(4), "two flights, two views");
                Assert.That(svg.Descendants(ns + "text").Any(t => t.Value == "net"), Is.True);
                Assert.That(svg.Descendants(ns + "text").Any(t => t.Value == "lob <&>"), Is.True);
                Assert.That(run.FirstResult().GetProperty("name").GetString(), Is.EqualTo("drive"), "JSON still goes to stdout");
            }
            finally
            {
                File.Delete(path);
            }
        }
    }
}
