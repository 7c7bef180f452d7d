using System;
using System.Collections.Generic;
using System.Text.Json.Nodes;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests.Api
{
    /// <summary>
    /// Every class of bad scenario file ends with exit code 2, nothing on stdout, and one stderr line that
    /// names the bad field by its JSON path.
    /// </summary>
    [TestFixture]
    public class BadScenarioTests
    {
        private static JsonObject S(JsonObject root) => CliRun.FirstScenario(root);

        private static IEnumerable<TestCaseData> Mutations()
        {
            TestCaseData Case(string name, Action<JsonObject> mutate, string expected) =>
                new TestCaseData(mutate, expected).SetName("BadScenario_" + name);

            // Missing required fields.
            yield return Case("MissingScenarios", r => r.Remove("scenarios"), "scenarios: required field is missing");
            yield return Case("EmptyScenarios", r => r["scenarios"] = new JsonArray(), "scenarios: must hold at least one scenario");
            yield return Case("ScenariosNotArray", r => r["scenarios"] = 3, "scenarios: must be an array");
            yield return Case("MissingBall", r => S(r).Remove("ball"), "scenarios[0].ball: required field is missing");
            yield return Case("MissingMass", r => S(r)["ball"]!.AsObject().Remove("mass"), "scenarios[0].ball.mass: required field is missing");
            yield return Case("NullRadius", r => S(r)["ball"]!["radius"] = null, "scenarios[0].ball.radius: must not be null");
            yield return Case("MissingInitial", r => S(r).Remove("initial"), "scenarios[0].initial: required field is missing");
            yield return Case("MissingVelocity", r => S(r)["initial"]!.AsObject().Remove("velocity"), "scenarios[0].initial.velocity: required field is missing");
            yield return Case("MissingModel", r => S(r)["aero"]!["drag"]!.AsObject().Remove("model"), "scenarios[0].aero.drag.model: required field is missing");
            yield return Case("MissingCd", r => S(r)["aero"]!["drag"]!.AsObject().Remove("cd"), "scenarios[0].aero.drag.cd: required field is missing");
            yield return Case("MissingTau", r => S(r)["spinDecay"] = new JsonObject { ["model"] = "exponential" }, "scenarios[0].spinDecay.tau: required field is missing");
            yield return Case("MissingPlaneName", r => S(r)["planes"]![0]!.AsObject().Remove("name"), "scenarios[0].planes[0].name: required field is missing");
            yield return Case("MissingPlanePoint", r => S(r)["planes"]![0]!.AsObject().Remove("point"), "scenarios[0].planes[0].point: required field is missing");
            yield return Case("MissingPlaneNormal", r => S(r)["planes"]![0]!.AsObject().Remove("normal"), "scenarios[0].planes[0].normal: required field is missing");

            // Unknown names.
            yield return Case("UnknownDragModel", r => S(r)["aero"]!["drag"]!["model"] = "quadratic",
                "scenarios[0].aero.drag.model: unknown model 'quadratic'; expected one of: none, constant, stepanek, linear-spin, goff-carre, nathan");
            yield return Case("UnknownLiftModel", r => S(r)["aero"]!["lift"]!["model"] = "magnus",
                "scenarios[0].aero.lift.model: unknown model 'magnus'; expected one of: none, constant, stepanek, linear-spin, goff-carre, nathan");
            yield return Case("UnknownSpinDecay", r => S(r)["spinDecay"]!["model"] = "linear", "scenarios[0].spinDecay.model: unknown model 'linear'");
            yield return Case("UnknownIntegrator", r => S(r)["integrator"] = "rk45", "scenarios[0].integrator: unknown integrator 'rk45'; expected one of: euler, semi-implicit-euler, heun, rk4, dp54");

            // Unknown fields: typos must not pass silently.
            yield return Case("TypoTopLevel", r => r["scenario"] = new JsonArray(), "scenario: unknown field; expected one of: scenarios");
            yield return Case("TypoInScenario", r => S(r)["maxtime"] = 3, "scenarios[0].maxtime: unknown field");
            yield return Case("TypoInBall", r => S(r)["ball"]!["radus"] = 0.03, "scenarios[0].ball.radus: unknown field");
            yield return Case("FieldOfAnotherModel", r => S(r)["aero"]!["drag"]!["cl"] = 0.2, "scenarios[0].aero.drag.cl: unknown field");
            yield return Case("ParameterOnStepanek", r => S(r)["aero"]!["lift"] = new JsonObject { ["model"] = "stepanek", ["cl"] = 0.2 },
                "scenarios[0].aero.lift.cl: unknown field");
            yield return Case("TypoInPlane", r => S(r)["planes"]![0]!["normals"] = new JsonArray(1, 0, 0), "scenarios[0].planes[0].normals: unknown field");
            yield return Case("TypoInInitial", r => S(r)["initial"]!["spin"] = new JsonArray(0, 0, 0), "scenarios[0].initial.spin: unknown field");

            // Non-finite and out-of-range numbers.
            yield return Case("OverflowingNumber", r => S(r)["ball"]!["mass"] = JsonNode.Parse("1e999"), "scenarios[0].ball.mass: must be a finite number; got 1e999");
            yield return Case("NaNAsString", r => S(r)["ball"]!["mass"] = "NaN", "scenarios[0].ball.mass: must be a finite number; got the string \"NaN\"");
            yield return Case("InfinityInVector", r => S(r)["initial"]!["velocity"]![1] = JsonNode.Parse("-1e400"), "scenarios[0].initial.velocity[1]: must be a finite number; got -1e400");
            yield return Case("NegativeMass", r => S(r)["ball"]!["mass"] = -1, "scenarios[0].ball.mass: must be finite and > 0; got -1");
            yield return Case("ZeroRadius", r => S(r)["ball"]!["radius"] = 0, "scenarios[0].ball.radius: must be finite and > 0; got 0");
            yield return Case("InertiaAboveOne", r => S(r)["ball"]!["inertiaFactor"] = 1.5, "scenarios[0].ball.inertiaFactor: must be in (0, 1]; got 1.5");
            yield return Case("NegativeDensity", r => S(r)["air"]!["density"] = -0.1, "scenarios[0].air.density: must be finite and >= 0; got -0.1");
            yield return Case("NegativeCd", r => S(r)["aero"]!["drag"]!["cd"] = -0.5, "scenarios[0].aero.drag.cd: must be finite and >= 0; got -0.5");
            yield return Case("ZeroStep", r => S(r)["step"] = 0, "scenarios[0].step: must be finite and > 0; got 0");
            yield return Case("NegativeStep", r => S(r)["step"] = -0.01, "scenarios[0].step: must be finite and > 0; got -0.01");
            yield return Case("NegativeMaxTime", r => S(r)["maxTime"] = -1, "scenarios[0].maxTime: must be finite and > 0; got -1");
            yield return Case("TooManySteps", r => { S(r)["maxTime"] = 1e6; S(r)["step"] = 1e-3; }, "scenarios[0].maxTime: maxTime / step must be at most");
            yield return Case("ZeroTau", r => S(r)["spinDecay"] = new JsonObject { ["model"] = "exponential", ["tau"] = 0 }, "scenarios[0].spinDecay.tau: must be finite and > 0; got 0");
            yield return Case("ZeroNormal", r => S(r)["planes"]![0]!["normal"] = new JsonArray(0, 0, 0), "scenarios[0].planes[0].normal: must be a non-zero direction; got [0, 0, 0]");
            yield return Case("ZeroGroundNormal", r => S(r)["ground"]!["normal"] = new JsonArray(0, 0, 0), "scenarios[0].ground.normal: must be a non-zero direction");
            yield return Case("BoundsReversed", r => S(r)["planes"]![0]!["bounds"] = new JsonObject { ["height"] = new JsonArray(1, 0) },
                "scenarios[0].planes[0].bounds.height: min must not exceed max; got [1, 0]");

            // Wrong shapes and types.
            yield return Case("VectorTooShort", r => S(r)["gravity"] = new JsonArray(0, -9.81), "scenarios[0].gravity: must be an array of 3 finite numbers [x, y, z]; got 2 elements");
            yield return Case("VectorTooLong", r => S(r)["initial"]!["position"] = new JsonArray(0, 0, 1, 0), "scenarios[0].initial.position: must be an array of 3 finite numbers [x, y, z]; got 4 elements");
            yield return Case("VectorAsNumber", r => S(r)["air"]!["wind"] = 0, "scenarios[0].air.wind: must be an array of 3 finite numbers [x, y, z]; got 0");
            yield return Case("StringForNumber", r => S(r)["step"] = "0.01", "scenarios[0].step: must be a finite number; got the string \"0.01\"");
            yield return Case("NumberForString", r => S(r)["integrator"] = 4, "scenarios[0].integrator: must be a string; got 4");
            yield return Case("BallNotObject", r => S(r)["ball"] = new JsonArray(0.057, 0.033), "scenarios[0].ball: must be an object; got an array");
            yield return Case("ScenarioNotObject", r => r["scenarios"]![0] = "drive", "scenarios[0]: must be an object; got the string \"drive\"");
            yield return Case("SecondScenarioBad", r => r["scenarios"]!.AsArray().Add(JsonNode.Parse("{\"ball\": {\"mass\": 1}}")),
                "scenarios[1].ball.radius: required field is missing");
        }

        [TestCaseSource(nameof(Mutations))]
        public void ExitsWithTwo_AndNamesTheField(Action<JsonObject> mutate, string expected)
        {
            JsonObject root = CliRun.Drive();
            mutate(root);
            CliRun run = CliRun.Simulate(root);
            Assert.Multiple(() =>
            {
                Assert.That(run.ExitCode, Is.EqualTo(2), run.Stderr);
                Assert.That(run.Stderr, Does.StartWith("magnusball: " + expected));
                Assert.That(run.Stdout, Is.Empty, "nothing goes to stdout on error");
            });
        }

        [TestCase("{\"scenarios\": [", "invalid JSON (line 1, column 16)", TestName = "BadJson_Truncated")]
        [TestCase("{\"scenarios\": [{\"ball\": {\"mass\": NaN}}]}", "scenarios[0].ball.mass: invalid JSON (line 1, column 34)", TestName = "BadJson_NaNLiteral")]
        [TestCase("{\"scenarios\": [{\"step\": Infinity}]}", "scenarios[0].step: invalid JSON", TestName = "BadJson_InfinityLiteral")]
        [TestCase("{\"scenarios\": [{\"initial\": {\"position\": [0, 0, -Infinity]}}]}", "scenarios[0].initial.position[2]: invalid JSON", TestName = "BadJson_NegativeInfinityInVector")]
        [TestCase("{\"scenarios\": [{}, {\"name\": 'x'}]}", "scenarios[1].name: invalid JSON", TestName = "BadJson_SingleQuotes")]
        [TestCase("", "invalid JSON", TestName = "BadJson_Empty")]
        [TestCase("[1, 2, 3]", ": must be an object; got an array", TestName = "BadJson_RootNotObject")]
        public void BadJson_ExitsWithTwo_AndSaysWhere(string json, string expected)
        {
            CliRun run = CliRun.Simulate(json);
            Assert.Multiple(() =>
            {
                Assert.That(run.ExitCode, Is.EqualTo(2), run.Stderr);
                Assert.That(run.Stderr, Does.Contain(expected));
                Assert.That(run.Stdout, Is.Empty);
            });
        }

        [Test]
        public void NaNLiteral_MessageSaysJsonHasNoNaN()
        {
            CliRun run = CliRun.Simulate("{\"scenarios\": [{\"ball\": {\"mass\": NaN}}]}");
            Assert.That(run.Stderr, Does.Contain("JSON has no NaN or Infinity"));
        }

        [Test]
        public void AnAimFile_GivenToSimulate_SaysToUseAim()
        {
            CliRun run = CliRun.Simulate("{\"aims\": [{\"name\": \"net\"}]}");
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr, Does.Contain("magnusball aim FILE"));
            Assert.That(run.Stdout, Is.Empty);
        }

        [Test]
        public void DuplicateField_IsAnError()
        {
            string json = CliRun.DriveJson.Replace("\"step\": 0.004166666666666667,", "\"step\": 0.004166666666666667, \"step\": 0.01,");
            CliRun run = CliRun.Simulate(json);
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr, Does.StartWith("magnusball: scenarios[0].step: field is given more than once"));
        }

        [Test]
        public void DivergingFlight_NamesTheStep()
        {
            // Explicit Euler on a 30 m/s ball at a 1 s step with a huge drag factor would blow up to infinity.
            JsonObject root = CliRun.Drive();
            JsonObject s = S(root);
            s["integrator"] = "euler";
            s["step"] = 1.0;
            s["air"]!["density"] = 1e6;
            s["ground"] = null;
            s["maxTime"] = 1000;
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.Stderr);
            // Refused before the step is taken: far beyond Euler's stability bound for this drag.
            Assert.That(run.Stderr, Does.StartWith("magnusball: scenarios[0].step: a step of 1 s is beyond euler's stability bound for this flight's drag at t = 0 s"));
            Assert.That(run.Stdout, Is.Empty);
        }
    }
}
