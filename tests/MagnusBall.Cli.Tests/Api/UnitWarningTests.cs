using System.Text.Json.Nodes;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests.Api
{
    /// <summary>
    /// With a preset, a ball or launch outside what the sport's real balls are and do gets one warning line per value on stderr,
    /// naming the field; the flight still runs, exit 0, and stdout is the result it always was. The limits are the library's
    /// SportLimits (tested there).
    /// </summary>
    [TestFixture]
    public class UnitWarningTests
    {
        private static JsonObject TennisShot(double mass, double spin) => JsonNode.Parse(
            "{\"scenarios\": [{\"preset\": \"tennis\", \"ball\": {\"mass\": " + mass.ToString(System.Globalization.CultureInfo.InvariantCulture) + "}," +
            " \"initial\": {\"position\": [0,0,1], \"velocity\": [30,0,3], \"angularVelocity\": [0," + spin.ToString(System.Globalization.CultureInfo.InvariantCulture) + ",0]}}]}")!.AsObject();

        [Test]
        public void ATennisBallOfMass57_AndSpinInRpm_AreWarnedAbout_AndStillFlown()
        {
            CliRun run = CliRun.Simulate(TennisShot(57, 2000));
            string[] lines = run.Stderr.TrimEnd('\n').Split('\n');
            Assert.Multiple(() =>
            {
                Assert.That(run.ExitCode, Is.EqualTo(0));
                Assert.That(lines, Has.Length.EqualTo(2));
                Assert.That(lines[0], Does.StartWith("magnusball: warning: scenarios[0].ball.mass: mass 57 kg is outside a tennis ball's 0.056-0.0594 kg; a mass in grams?"));
                Assert.That(lines[1], Does.StartWith("magnusball: warning: scenarios[0].initial.angularVelocity: spin 19098.5932 rpm (2000 rad/s)"));
                Assert.That(lines[1], Does.Contain("a rate in rpm typed where rad/s is meant?"));
                Assert.That(run.FirstResult().GetProperty("landing").ValueKind, Is.EqualTo(System.Text.Json.JsonValueKind.Object));
            });
        }

        [Test]
        public void APlausibleShot_HasNoWarning_AndTheSameOutput()
        {
            CliRun plain = CliRun.Simulate(TennisShot(0.057, 200));
            Assert.That(plain.ExitCode, Is.EqualTo(0));
            Assert.That(plain.Stderr, Is.Empty);

            // The warned flight prints what it printed before the guard: the result is the same bits either way.
            JsonObject heavySpin = TennisShot(0.057, 2000);
            CliRun warned = CliRun.Simulate(heavySpin);
            Assert.That(warned.Stderr, Is.Not.Empty);
            Assert.That(warned.Stdout, Does.StartWith("{"));
        }

        [Test]
        public void WithoutAPreset_NothingIsWarned()
        {
            JsonObject root = CliRun.Drive();
            CliRun.FirstScenario(root)["ball"] = new JsonObject { ["mass"] = 57, ["radius"] = 0.033 };
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(0));
            Assert.That(run.Stderr, Is.Empty, "the tool cannot know the sport of a ball without a preset");
        }

        [Test]
        public void AnInputError_StaysOneLine_EvenWithAWarning()
        {
            JsonObject root = TennisShot(0.057, 2000); // the spin is warned about
            CliRun.FirstScenario(root)["step"] = 5.0; // beyond RK4's stability bound for this ball: exit 2
            CliRun run = CliRun.Simulate(root);
            Assert.That(run.ExitCode, Is.EqualTo(2));
            Assert.That(run.Stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), run.Stderr);
            Assert.That(run.Stderr, Does.Not.Contain("warning"));
        }

        [Test]
        public void Aim_WarnsAboutItsLaunchSpeed()
        {
            var root = JsonNode.Parse(
                "{\"aims\": [{\"preset\": \"tennis\", \"launch\": {\"position\": [0,0,1]}," +
                " \"find\": {\"kind\": \"elevation-to-reach\", \"speed\": 108, \"target\": [20,0,0]}}]}")!;
            var stdout = new System.IO.StringWriter();
            var stderr = new System.IO.StringWriter();
            int code = Program.Run(new[] { "aim", "-" }, stdout, stderr, new System.IO.StringReader(root.ToJsonString()));
            Assert.That(code, Is.EqualTo(0), stderr.ToString());
            Assert.That(stderr.ToString(), Does.StartWith("magnusball: warning: aims[0].find.speed: speed 108 m/s is above the fastest a tennis ball flies, 75 m/s; a speed in km/h or mph?"));
        }

        [Test]
        public void Help_CarriesTheFormats_NotAPointerToAFile()
        {
            CliRun run = CliRun.Of("--help");
            Assert.Multiple(() =>
            {
                Assert.That(run.ExitCode, Is.EqualTo(0));
                Assert.That(run.Stdout, Does.Not.Contain("docs/cli.md"));
                foreach (string field in new[] { "\"scenarios\"", "preset", "initial", "integrator", "\"aims\"", "find", "minimum-elevation-to-clear", "exit codes", "warning" })
                {
                    Assert.That(run.Stdout, Does.Contain(field));
                }
            });
        }
    }
}
