using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Xml.Linq;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests.Api
{
    /// <summary>
    /// The hostile inputs of issue 15, one regression test each: every one used to crash the tool with a stack
    /// trace, loop until out of memory, write invalid XML, or say something misleading.
    /// </summary>
    [TestFixture]
    public class HostileInputTests
    {
        private static JsonObject S(JsonObject root) => CliRun.FirstScenario(root);

        private static void AssertInputError(CliRun run, string expectedStart)
        {
            Assert.That(run.ExitCode, Is.EqualTo(Program.BadInput), run.Stderr);
            Assert.That(run.Stdout, Is.Empty);
            Assert.That(run.Stderr, Does.StartWith("magnusball: " + expectedStart));
            Assert.That(run.Stderr.TrimEnd('\n'), Does.Not.Contain("\n"), "one line, no stack trace");
        }

        [TestCase("""{"scenarios": [{"name": "\ud800", "ball": {"mass": 0.057, "radius": 0.033}, "initial": {"position": [0,0,1], "velocity": [1,0,1]}}]}""",
            "scenarios[0].name: the string holds a lone UTF-16 surrogate")]
        [TestCase("""{"scenarios": [{"ball": {"mass": 0.057, "radius": 0.033}, "integrator": "rk\udc004", "initial": {"position": [0,0,1], "velocity": [1,0,1]}}]}""",
            "scenarios[0].integrator: the string holds a lone UTF-16 surrogate")]
        [TestCase("""{"scenarios": [{"\ud800x": 1, "ball": {"mass": 0.057, "radius": 0.033}, "initial": {"position": [0,0,1], "velocity": [1,0,1]}}]}""",
            "scenarios[0]: a field name holds a lone UTF-16 surrogate")]
        public void LoneSurrogate_IsAnInputError(string json, string expected)
        {
            AssertInputError(CliRun.Simulate(json), expected);
        }

        [Test]
        public void LoneSurrogateCharacter_InTheText_IsAnInputError()
        {
            // Not an escape but the UTF-16 code unit itself (a string handed to Program.Run by a host).
            CliRun run = CliRun.Simulate(CliRun.DriveJson.Replace("\"drive\"", "\"a\ud800b\""));
            Assert.That(run.ExitCode, Is.EqualTo(Program.BadInput), run.Stderr);
            Assert.That(run.Stderr.TrimEnd('\n'), Does.Not.Contain("\n"));
        }

        [Test]
        public void LoneSurrogate_InAnAimFile_IsAnInputError()
        {
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            int code = Program.Run(new[] { "aim", "-" }, stdout, stderr, new StringReader("""{"aims": [{"name": "\udfff"}]}"""));
            Assert.That(code, Is.EqualTo(Program.BadInput), stderr.ToString());
            Assert.That(stderr.ToString(), Does.StartWith("magnusball: aims[0].name: the string holds a lone UTF-16 surrogate"));
        }

        [TestCase("rk4", "scenarios[0].step: a step of 0.004166666666666667 s is beyond rk4's stability bound for this flight's drag at t = 0 s (1E+155 m/s); the largest stable step there is 4.31639")]
        [TestCase("stable-rk4", "scenarios[0].step: the flight diverged (the state would not be finite after t = 0 s with stable-rk4)")]
        public void Divergence_ExitsWith2_ForEveryIntegrator(string integrator, string expected)
        {
            // v = 1e155 m/s: the drag overflows within the first step. A plain method's step is refused before it is
            // taken (beyond its stability bound); stable-rk4 takes it in substeps and diverges (it used to throw from one).
            JsonObject root = CliRun.Drive();
            S(root)["integrator"] = integrator;
            S(root)["initial"]!["velocity"] = new JsonArray(1e155, 0, 0);
            AssertInputError(CliRun.Simulate(root), expected);
        }

        [TestCase("euler", 2.0)]
        [TestCase("heun", 2.0)]
        [TestCase("rk4", 2.5)]
        [TestCase("dp54", 2.5)]
        public void StepBeyondTheStabilityBound_IsRefused_NamingTheLargestStableStep(string integrator, double bound)
        {
            // A table-tennis ball (2.7 g, 20 mm) at 100 m/s with the drive's constant C_D 0.55 and C_L 0.175, 125.7 rad/s.
            // StableIntegrator's remarks define the check: sigma = 1.1 x 2 k s_max (C_D + |C_L|) (no spin decay here;
            // s_max = s + |g| h <= 1.1 s), and a step is taken whole while h sigma <= the method's bound. The largest such
            // step solves h = bound / sigma(h), found here by fixed-point iteration from the formula, not by the CLI's code.
            JsonObject root = CliRun.Drive();
            S(root)["ball"] = new JsonObject { ["mass"] = 0.0027, ["radius"] = 0.02 };
            S(root)["initial"]!["velocity"] = new JsonArray(100, 0, 5);
            S(root)["integrator"] = integrator;
            double k = 1.21 * Math.PI * 0.02 * 0.02 / (2 * 0.0027), s = Math.Sqrt(100 * 100 + 5 * 5), h = 0.05;
            for (int i = 0; i < 100; i++)
            {
                h = bound / (1.1 * 2 * k * (s + 9.81 * h) * (0.55 + 0.175));
            }

            // Just above the bound: refused, exit 2, no landing printed, the largest stable step named.
            S(root)["step"] = h * 1.01;
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(Program.BadInput), run.Stderr);
            Assert.That(run.Stdout, Is.Empty, "no landing is printed");
            Assert.That(run.Stderr, Does.StartWith($"magnusball: scenarios[0].step: a step of {JsonFields.Format(h * 1.01)} s is beyond {integrator}'s stability bound"));
            string text = run.Stderr.Substring(run.Stderr.IndexOf("the largest stable step there is ", StringComparison.Ordinal) + 33);
            double named = double.Parse(text.Substring(0, text.IndexOf(' ')), System.Globalization.CultureInfo.InvariantCulture);
            // 1e-9: the bisection resolves the step to about 1e-18 relative; the check's own arithmetic (its ceiling of
            // h sigma / bound) and the formula's order of operations differ by rounding only.
            Assert.That(named, Is.EqualTo(h).Within(1e-9 * h));

            // The named step, and one just below it: taken, and the flight lands.
            foreach (double taken in new[] { named, h * 0.99 })
            {
                S(root)["step"] = taken;
                CliRun again = CliRun.Simulate(root);
                Assert.That(again.ExitCode, Is.EqualTo(0), again.Stderr);
                Assert.That(again.FirstResult().GetProperty("landing").ValueKind, Is.EqualTo(System.Text.Json.JsonValueKind.Object));
            }
        }

        [Test]
        public void Svg_OfAFlightFarFromTheOrigin_IsBoundedAndValid()
        {
            // Position y 1e12: the top view's lateral axis spans millimetres at 1e12 m, where a tick step was
            // below a double's resolution and the tick loop never ended (4.3 GB before).
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["position"] = new JsonArray(0, 1e12, 1);
            XDocument svg = DrawnSvg(root, out CliRun run);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            AssertCoordinatesFinite(svg);
            XNamespace ns = "http://www.w3.org/2000/svg";
            int gridLines = svg.Descendants(ns + "line").Count(l => (string?)l.Attribute("stroke") == "#e4e4e4");
            Assert.That(gridLines, Is.InRange(1, 4 * TrajectorySvg.MaxTicksPerAxis), "two views, two axes each, capped");
        }

        [TestCase(1e300)]
        [TestCase(-1.7e308)]
        [TestCase(1e-300)]
        public void Svg_OfExtremeButFiniteFlights_IsValid(double y)
        {
            JsonObject root = CliRun.Drive();
            S(root)["gravity"] = new JsonArray(0, 0, 0);
            S(root)["ground"] = null;
            S(root)["maxTime"] = 0.1;
            S(root)["initial"]!["position"] = new JsonArray(0, y, 1);
            XDocument svg = DrawnSvg(root, out CliRun run);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            AssertCoordinatesFinite(svg);
        }

        [Test]
        public void Svg_OfAnAxisSpanningTheWholeDoubleRange_HasOnlyFiniteTickLabels()
        {
            // A ball 1.7e308 m up over a ground 1.7e308 m down: the side view's height axis runs up to double.MaxValue, where
            // the tick loop's end test (t <= max + 1e-9 step) rounded to infinity and let 25 "Infinity" ticks through.
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["position"] = new JsonArray(0, 0, 1.7e308);
            S(root)["ground"] = new JsonObject { ["point"] = new JsonArray(0, 0, -1.7e308), ["normal"] = new JsonArray(0, 0, 1) };
            S(root)["maxTime"] = 0.5;
            XDocument svg = DrawnSvg(root, out CliRun run);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            AssertCoordinatesFinite(svg);
            XNamespace ns = "http://www.w3.org/2000/svg";
            string[] labels = svg.Descendants(ns + "text").Where(t => (string?)t.Attribute("text-anchor") == "end").Select(t => t.Value).ToArray();
            Assert.That(labels, Is.Not.Empty);
            foreach (string label in labels)
            {
                Assert.That(double.IsFinite(double.Parse(label, CultureInfo.InvariantCulture)), Is.True, label);
            }
        }

        [Test]
        public void Svg_WithControlCharactersInNames_IsWellFormedXml()
        {
            JsonObject root = CliRun.Drive();
            S(root)["name"] = "a\u0001b\u0000c\uffff\ufffe d\U0001F3BE";
            S(root)["planes"]![0]!["name"] = "net\u001b";
            XDocument svg = DrawnSvg(root, out CliRun run); // XDocument.Load throws on any character XML forbids
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            XNamespace ns = "http://www.w3.org/2000/svg";
            string[] texts = svg.Descendants(ns + "text").Select(t => t.Value).ToArray();
            // Forbidden characters become U+FFFD; a valid surrogate pair (a tennis ball emoji) stays.
            Assert.That(texts, Does.Contain("a\ufffdb\ufffdc\ufffd\ufffd d\U0001F3BE"));
            Assert.That(texts, Does.Contain("net\ufffd"));
            // The JSON keeps the name as given (escaped by the JSON writer).
            Assert.That(run.FirstResult().GetProperty("name").GetString(), Is.EqualTo("a\u0001b\u0000c\uffff\ufffe d\U0001F3BE"));
        }

        [Test]
        public void Samples_OfALongFlight_KeepOnlyTheStepsThatHoldThem()
        {
            // No gravity, step 1e-5 s for 2 s: 200,000 steps (the 1e-6 s for 10 s took 3.9 GB for 10 samples).
            JsonObject root = CliRun.Drive();
            S(root)["gravity"] = new JsonArray(0, 0, 0);
            S(root)["step"] = 1e-5;
            S(root)["maxTime"] = 2;
            Scenario scenario = ScenarioReader.Read(root.ToJsonString()).Single();

            FlightResult sparse = ScenarioFlight.Simulate(scenario, new Recording(false, new[] { 10 }), new WorkBudget(ScenarioFlight.MaxEvaluationsPerFile));
            Assert.That(sparse.Steps, Is.EqualTo(200_000));
            Assert.That(sparse.Points!.Count, Is.LessThanOrEqualTo(2 * 10), "two step ends per sample at most");

            // The samples are the ones the full recording gives, bit for bit (the same steps, flown again).
            FlightResult full = ScenarioFlight.Simulate(scenario, new Recording(true, Array.Empty<int>()), new WorkBudget(ScenarioFlight.MaxEvaluationsPerFile));
            Assert.That(full.Points!.Count, Is.EqualTo(200_001));
            FlightState[] a = ResultWriter.Sample(sparse, 10).ToArray();
            FlightState[] b = ResultWriter.Sample(full, 10).ToArray();
            for (int i = 0; i < 10; i++)
            {
                Assert.That(a[i].Position, Is.EqualTo(b[i].Position), $"sample {i}");
                Assert.That(a[i].Velocity, Is.EqualTo(b[i].Velocity), $"sample {i}");
                Assert.That(a[i].Time, Is.EqualTo(b[i].Time), $"sample {i}");
            }
        }

        [Test]
        public void Samples_OfAShortFlight_AreFlownOnce()
        {
            Scenario scenario = ScenarioReader.Read(CliRun.DriveJson).Single();
            var budget = new WorkBudget(ScenarioFlight.MaxEvaluationsPerFile);
            FlightResult r = ScenarioFlight.Simulate(scenario, new Recording(false, new[] { 10, TrajectorySvg.SamplesPerFlight }), budget);
            Assert.That(r.Points!.Count, Is.EqualTo(r.Steps + 1), "every step kept: below ScenarioFlight.MaxKeptPoints");
            Assert.That(budget.Total, Is.EqualTo(r.DerivativeEvaluations), "one flight's evaluations spent, not two");
        }

        [Test]
        public void WorkBudget_StopsAFileWithAClearError()
        {
            Scenario scenario = ScenarioReader.Read(CliRun.DriveJson).Single(); // rk4, 183 steps to the landing
            // 1 evaluation at the start and 4 a step: 401 pays for exactly 100 steps, and the 101st is refused.
            var budget = new WorkBudget(401);
            var error = Assert.Throws<InputError>(() => ScenarioFlight.Simulate(scenario, Recording.None, budget))!;
            Assert.That(error.Message, Does.StartWith(
                "scenarios[0].step: the file's flights need more than 401 model evaluations (rk4 makes 4 per step; this flight reached t = 0.41666"));
            Assert.That(error.Message, Does.Contain("at most 401 are allowed per file"));
            Assert.That(budget.Total, Is.EqualTo(401));
        }

        [Test]
        public void WorkBudget_CountsTheModelsRealCalls()
        {
            // The budget is charged before each step; for a fixed-step method it must equal the model's real calls,
            // counted here by a drag law that counts them (every evaluation asks the drag law once).
            Scenario drive = ScenarioReader.Read(CliRun.DriveJson).Single();
            foreach (string name in new[] { "euler", "heun", "rk4", "dp54" })
            {
                var counting = new CountingDrag();
                Scenario scenario = drive with { Model = drive.Model.WithDrag(counting), Integrator = MagnusBall.Integration.Integrators.FromName(name) };
                var budget = new WorkBudget(ScenarioFlight.MaxEvaluationsPerFile);
                FlightResult r = ScenarioFlight.Simulate(scenario, Recording.None, budget);
                Assert.That(r.Landing, Is.Not.Null, name);
                Assert.That(budget.Total, Is.EqualTo(r.DerivativeEvaluations), name);
                // Each evaluation asks the law once; the stability check asks it once or twice more a step (the stiffness
                // rate at the speed and at the fastest speed within the step), outside the flight's evaluations.
                Assert.That(counting.Calls - budget.Total, Is.InRange(r.Steps, 2 * r.Steps), name);
            }
        }

        [Test]
        public void TinyDormandPrinceStep_IsRefusedWithinTheBudget_NotRunFor12Seconds()
        {
            // The slowest of 10,000 hostile files (issue 15): dp54 at a 1e-6 s step, 760,000 steps of 6 evaluations (the
            // old cap counted steps, 1e7 a file, so it ran 11.9 s). Here with the budget lowered to keep the suite fast (1 + 6 x 100,000
            // steps: t = 0.1 s); the default is ScenarioFlight.MaxEvaluationsPerFile.
            JsonObject root = CliRun.Drive();
            S(root)["integrator"] = "dp54";
            S(root)["step"] = 1e-6;
            S(root)["maxTime"] = 0.76;
            long saved = ScenarioFlight.EvaluationsPerFileLimit;
            ScenarioFlight.EvaluationsPerFileLimit = 600_001;
            try
            {
                CliRun run = CliRun.Simulate(root);
                AssertInputError(run, "scenarios[0].step: the file's flights need more than 600001 model evaluations (dp54 makes 6 per step; this flight reached t = 0.10000000000");
                Assert.That(run.Stderr, Does.Contain("use a larger step, a shorter maxTime or a cheaper integrator"));
            }
            finally
            {
                ScenarioFlight.EvaluationsPerFileLimit = saved;
            }
        }

        [Test]
        public void WorkBudget_CountsTheSubstepsOfStableRk4()
        {
            // A 1 mg ball at 300 m/s: k C_D s h is about 1400 at the launch, so stable-rk4 splits the first steps into
            // hundreds of substeps (the ball then slows to its 0.09 m/s terminal speed, one substep a step).
            JsonObject root = CliRun.Drive();
            S(root)["ball"] = new JsonObject { ["mass"] = 1e-6, ["radius"] = 0.033 };
            S(root)["initial"]!["velocity"] = new JsonArray(300, 0, 10);
            S(root)["maxTime"] = 1;
            // Plain RK4 at 1/240 s is far beyond its stability bound here: refused before its first step.
            var rk4 = new WorkBudget(ScenarioFlight.MaxEvaluationsPerFile);
            InputError refused = Assert.Throws<InputError>(() => ScenarioFlight.Simulate(ScenarioReader.Read(root.ToJsonString()).Single(), Recording.None, rk4))!;
            Assert.That(refused.Message, Does.Contain("beyond rk4's stability bound"));
            Assert.That(rk4.Total, Is.EqualTo(1), "only the start's evaluation");

            S(root)["integrator"] = "stable-rk4";
            var stable = new WorkBudget(ScenarioFlight.MaxEvaluationsPerFile);
            FlightResult r = ScenarioFlight.Simulate(ScenarioReader.Read(root.ToJsonString()).Single(), Recording.None, stable);
            TestContext.Out.WriteLine($"stable-rk4: {r.Steps} steps, {stable.Total} evaluations charged, {r.DerivativeEvaluations} made");
            Assert.That(stable.Total, Is.GreaterThan(4 * r.Steps + 4000), "substeps charged, not steps");
            Assert.That(stable.Total, Is.GreaterThanOrEqualTo(r.DerivativeEvaluations), "the charge is an upper estimate of the work done");
        }

        private sealed class CountingDrag : MagnusBall.Aerodynamics.IDragModel
        {
            public long Calls;

            public double DragCoefficient(in MagnusBall.Aerodynamics.AeroConditions conditions)
            {
                Calls++;
                return 0.55;
            }
        }

        [TestCase(1e15)]
        [TestCase(-1e15)]
        [TestCase(1e300)]
        public void StartTimeTooLargeForTheStep_SaysTimeCannotAdvance(double time)
        {
            // 1e15 s used to say "the flight diverged ... use a smaller step" (the state was finite), 1e300 s exited 0
            // having taken no step.
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["time"] = time;
            CliRun run = CliRun.Simulate(root);
            AssertInputError(run, "scenarios[0].initial.time: time cannot advance");
            Assert.That(run.Stderr, Does.Not.Contain("diverged"));
        }

        [Test]
        public void StartTimeWhoseEndOverflows_SaysTimeCannotAdvance_WithoutNaN()
        {
            // 1.7e308 s plus a maxTime of 1e308 s is past the largest double: the message said "at |t| = Infinity s a double
            // resolves only NaN s".
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["time"] = 1.7e308;
            S(root)["maxTime"] = 1e308;
            S(root)["step"] = 1e307;
            CliRun run = CliRun.Simulate(root);
            AssertInputError(run, "scenarios[0].initial.time: time cannot advance: the flight would end past the largest double");
            Assert.That(run.Stderr, Does.Not.Contain("NaN").And.Not.Contain("Infinity"));
        }

        [Test]
        public void StartTimeThatTheStepResolves_StillFlies()
        {
            // At 1e6 s a double resolves 1.2e-10 s: a 1/240 s step is 3.6e7 of those.
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["time"] = 1e6;
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            Assert.That(run.FirstResult().GetProperty("landing").GetProperty("time").GetDouble() - 1e6, Is.EqualTo(0.7617).Within(1e-3));
        }

        [TestCase(1e308)]
        [TestCase(1e-300)]
        [TestCase(-1e-320)]
        public void GroundNormal_OfAnyFiniteLength_IsADirection(double z)
        {
            // 1e308 was "must be a non-zero direction" (its squared length overflowed); 1e-300 underflowed.
            JsonObject root = CliRun.Drive();
            S(root)["ground"]!["normal"] = new JsonArray(0, 0, Math.Abs(z));
            S(root)["planes"]![0]!["normal"] = new JsonArray(z > 0 ? z : -z, 0, 0);
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            CliRun reference = CliRun.Simulate(CliRun.DriveJson);
            Assert.That(run.FirstResult().GetProperty("landing").GetRawText(), Is.EqualTo(reference.FirstResult().GetProperty("landing").GetRawText()));
            Assert.That(run.FirstResult().GetProperty("crossings").GetRawText(), Is.EqualTo(reference.FirstResult().GetProperty("crossings").GetRawText()));
        }

        [TestCase(2.0, null, true, TestName = "FarBoundedNet_UnboundedWidth_IsInside")]
        [TestCase(2.0, 6.4, false, TestName = "FarBoundedNet_FiniteWidth_IsOutside")]
        [TestCase(0.914, null, false, TestName = "FarBoundedNet_BallAboveTheTape_IsNotInside")]
        public void BoundedPlane_WhosePointIsBeyondDoubleRangeFromTheCrossing_ReportsInsideByItsLimits(double netHeight, double? halfWidth, bool inside)
        {
            // The drive flown at y = 1e308 past a net whose point is at y = -1e308: the crossing is 2e308 from the net's point
            // along the width axis (0, -1, 0), so position - point overflows in y. The height was inf * 0 = NaN and every
            // crossing was "not inside"; now the height is the true 1.35 m and the width -inf: outside a finite width limit,
            // inside a missing one. Wind is zero and nothing depends on y, so the flight in x and z is the reference drive's.
            JsonObject root = CliRun.Drive();
            S(root)["initial"]!["position"] = new JsonArray(0, 1e308, 1);
            var bounds = new JsonObject { ["height"] = new JsonArray(0, netHeight) };
            if (halfWidth is double w)
            {
                bounds["width"] = new JsonArray(-w, w);
            }

            S(root)["planes"]![0]!["point"] = new JsonArray(11.885, -1e308, 0);
            S(root)["planes"]![0]!["bounds"] = bounds;
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement crossing = run.FirstResult().GetProperty("crossings")[0];
            JsonElement reference = CliRun.Simulate(CliRun.DriveJson).FirstResult().GetProperty("crossings")[0];
            Assert.That(crossing.GetProperty("time").GetDouble(), Is.EqualTo(reference.GetProperty("time").GetDouble()));
            Assert.That(crossing.GetProperty("inside").GetBoolean(), Is.EqualTo(inside));
        }

        [Test]
        public void PlaneBoundsCoordinates_OfFarPoints_AreNeverNaN_AndTheCommonCaseIsThePlainFormula()
        {
            double r = Math.Sqrt(0.5);
            var bounds = new PlaneBounds(new Vector3d(r, -r, 0), new Vector3d(0, 0, 1), 0, 1, double.NegativeInfinity, double.PositiveInfinity);
            // position - origin = (2e308, 2e308, 0) overflows to (inf, inf, 0): the plain height is inf - inf = NaN, the
            // true one 0 (both components cancel; quartered, (5e307 r - 5e307 r) is exactly 0).
            (double height, double width) = bounds.Coordinates(new Vector3d(1e308, 1e308, 0.5), new Vector3d(-1e308, -1e308, 0));
            Assert.That(height, Is.EqualTo(0));
            Assert.That(width, Is.EqualTo(0.5));
            Assert.That(bounds.Contains(new Vector3d(1e308, 1e308, 0.5), new Vector3d(-1e308, -1e308, 0)), Is.True);

            // Beyond what a double holds along an axis: infinite with the true sign, never NaN (the true height is
            // 3.4e308 * 2 r = 4.8e308 > double.MaxValue; the plain formula gave inf - (-inf) = inf here only by luck of signs,
            // so this pins the sign through the quarters).
            (height, _) = bounds.Coordinates(new Vector3d(1.7e308, -1.7e308, 0), new Vector3d(-1.7e308, 1.7e308, 0));
            Assert.That(height, Is.EqualTo(double.PositiveInfinity));

            // Where the plain formula is finite, the result is it, to the bit.
            var random = new Random(11);
            for (int i = 0; i < 1000; i++)
            {
                double scale = Math.Pow(10, random.Next(-300, 308));
                var p = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * scale;
                var o = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * scale;
                (double h, double w) = bounds.Coordinates(p, o);
                Assert.That(h, Is.EqualTo(Vector3d.Dot(p - o, bounds.HeightAxis)));
                Assert.That(w, Is.EqualTo(Vector3d.Dot(p - o, bounds.WidthAxis)));
            }
        }

        private static CliRun Aim(string ground, string position, string find)
        {
            string json = """{"aims": [{"name": "a", "ball": {"mass": 0.057, "radius": 0.033}, "air": {"density": 1.21}, "gravity": [0, 0, -9.81], """ +
                          """ "integrator": "rk4", "step": 0.004166666666666667, "maxTime": 5, "ground": """ + ground +
                          """, "launch": {"position": """ + position + """}, "find": """ + find + "}]}";
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            int code = Program.Run(new[] { "aim", "-" }, stdout, stderr, new StringReader(json));
            return new CliRun(code, stdout.ToString(), stderr.ToString());
        }

        [Test]
        public void AimClearance_BeyondDoubleRange_IsWrittenAsTheLargestDouble()
        {
            // A launch 1.7e308 m up over a ground 1.7e308 m down: every trial clears 1 m by 3.4e308 m, infinite in the
            // library. The JSON writer refused the infinity and the tool ended with "internal error" (exit 1).
            CliRun run = Aim("""{"point": [0, 0, -1.7e308], "normal": [0, 0, 1]}""", "[0, 0, 1.7e308]",
                """{"kind": "minimum-elevation-to-clear", "speed": 30, "plane": {"point": [11.885, 0, 0], "normal": [1, 0, 0]}, "height": 1}""");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement r = run.FirstResult();
            Assert.That(r.GetProperty("status").GetString(), Is.EqualTo("solved"));
            Assert.That(r.GetProperty("elevationDegrees").GetDouble(), Is.EqualTo(-45), "the lowest elevation tried already clears");
            Assert.That(r.GetProperty("miss").GetDouble(), Is.EqualTo(double.MaxValue));
        }

        [TestCase("elevation-to-reach", "\"speed\": 30")]
        [TestCase("angles-to-reach", "\"speed\": 30")]
        [TestCase("speed-to-reach", "\"elevationDegrees\": 10")]
        public void AimAtATargetBeyondDoubleRange_IsUnreachable(string kind, string parameter)
        {
            // The launch at y = 1e308, the target at y = -1e308: their difference overflows. It was exit 2, "target must
            // not be straight above or below the launch point (horizontal distance NaN m)".
            CliRun run = Aim("""{"point": [0, 0, 0], "normal": [0, 0, 1]}""", "[0, 1e308, 1]",
                "{\"kind\": \"" + kind + "\", " + parameter + ", \"target\": [20, -1e308, 0]}");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            Assert.That(run.FirstResult().GetProperty("status").GetString(), Is.EqualTo("unreachable"));
        }

        private static IEnumerable<TestCaseData> NullFields()
        {
            TestCaseData Case(string name, Action<JsonObject> mutate, string path) => new TestCaseData(mutate, path).SetName("Null_" + name);
            yield return Case("Step", r => S(r)["step"] = null, "scenarios[0].step");
            yield return Case("MaxTime", r => S(r)["maxTime"] = null, "scenarios[0].maxTime");
            yield return Case("Gravity", r => S(r)["gravity"] = null, "scenarios[0].gravity");
            yield return Case("Integrator", r => S(r)["integrator"] = null, "scenarios[0].integrator");
            yield return Case("AirDensity", r => S(r)["air"]!["density"] = null, "scenarios[0].air.density");
            yield return Case("Air", r => S(r)["air"] = null, "scenarios[0].air");
            yield return Case("Name", r => S(r)["name"] = null, "scenarios[0].name");
            yield return Case("Wind", r => S(r)["air"]!["wind"] = null, "scenarios[0].air.wind");
            yield return Case("Drag", r => S(r)["aero"]!["drag"] = null, "scenarios[0].aero.drag");
            yield return Case("Planes", r => S(r)["planes"] = null, "scenarios[0].planes");
            yield return Case("AngularVelocity", r => S(r)["initial"]!["angularVelocity"] = null, "scenarios[0].initial.angularVelocity");
            yield return Case("Preset", r => S(r)["preset"] = null, "scenarios[0].preset");
        }

        [TestCaseSource(nameof(NullFields))]
        public void Null_IsAnInputError_NamingTheField(Action<JsonObject> mutate, string path)
        {
            // The format gives null a meaning only for "ground"; elsewhere it used to mean "default" silently.
            JsonObject root = CliRun.Drive();
            mutate(root);
            AssertInputError(CliRun.Simulate(root), path + ": must not be null (leave the field out to get its default)");
        }

        [Test]
        public void NullGround_StillSwitchesTheGroundOff()
        {
            JsonObject root = CliRun.Drive();
            S(root)["ground"] = null;
            S(root)["maxTime"] = 1;
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            Assert.That(run.FirstResult().GetProperty("landing").ValueKind, Is.EqualTo(JsonValueKind.Null));
        }

        [Test]
        public void AimScan_WithTooManyTrials_IsAnInputError()
        {
            // elevationScanDegrees 1e-6 over the default [-45, 80] deg: 1.25e8 trial flights (it ran > 60 s before).
            const string json = """
                {"aims": [{"ball": {"mass": 0.057, "radius": 0.033}, "launch": {"position": [0, 0, 1]},
                  "limits": {"elevationScanDegrees": 1e-6},
                  "find": {"kind": "elevation-to-reach", "speed": 30, "target": [20, 0, 0]}}]}
                """;
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            int code = Program.Run(new[] { "aim", "-" }, stdout, stderr, new StringReader(json));
            Assert.That(code, Is.EqualTo(Program.BadInput), stderr.ToString());
            Assert.That(stderr.ToString(), Does.StartWith("magnusball: aims[0].limits.elevationScanDegrees: the scan would fly 125000000 trial shots"));
            Assert.That(stderr.ToString(), Does.Contain("at most 10000"));
        }

        internal static XDocument DrawnSvg(JsonNode root, out CliRun run)
        {
            string path = Path.Combine(Path.GetTempPath(), $"magnusball-{Guid.NewGuid():N}.svg");
            try
            {
                run = CliRun.Simulate(root, "--svg", path);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
                return XDocument.Load(path);
            }
            finally
            {
                File.Delete(path);
            }
        }

        internal static void AssertCoordinatesFinite(XDocument svg)
        {
            foreach (XAttribute a in svg.Descendants().Attributes())
            {
                string name = a.Name.LocalName;
                if (name is "x" or "y" or "x1" or "x2" or "y1" or "y2" or "cx" or "cy" or "width" or "height")
                {
                    Assert.That(double.TryParse(a.Value, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) && double.IsFinite(v), Is.True, $"{name}=\"{a.Value}\"");
                }
                else if (name == "points")
                {
                    foreach (string pair in a.Value.Split(' ', StringSplitOptions.RemoveEmptyEntries))
                    {
                        Assert.That(pair.Split(',').All(c => double.TryParse(c, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) && double.IsFinite(v)), Is.True, pair);
                    }
                }
            }
        }
    }
}
