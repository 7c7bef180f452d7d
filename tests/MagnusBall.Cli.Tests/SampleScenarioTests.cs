using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests
{
    /// <summary>
    /// The scenario files committed under samples/scenarios (the ones the figures in docs/figures are drawn
    /// from) run and still show what the figures claim.
    /// </summary>
    [TestFixture]
    public class SampleScenarioTests
    {
        internal static string RepositoryFile(string relative)
        {
            var dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory);
            while (dir != null && !File.Exists(Path.Combine(dir.FullName, "MagnusBall.sln")))
            {
                dir = dir.Parent;
            }

            Assert.That(dir, Is.Not.Null, "repository root (MagnusBall.sln) not found above the test directory");
            return Path.Combine(dir!.FullName, relative);
        }

        private static JsonElement[] Results(string file)
        {
            CliRun run = CliRun.Of("simulate", RepositoryFile(file));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            return run.Json().GetProperty("results").EnumerateArray().ToArray();
        }

        private static JsonElement Crossing(JsonElement result, string plane) =>
            result.GetProperty("crossings").EnumerateArray().Single(c => c.GetProperty("name").GetString() == plane);

        [Test]
        public void Drive_IsTheIssueExample()
        {
            JsonElement r = Results("samples/scenarios/drive.json").Single();
            Assert.That(r.GetProperty("landing").GetProperty("position")[0].GetDouble(), Is.EqualTo(18.666).Within(0.001));
        }

        [Test]
        public void Cross2011_EveryShotClearsTheNet_AndTheBaselineShotsLandAtTheBaseline()
        {
            JsonElement[] r = Results("samples/scenarios/cross2011.json");
            Assert.That(r, Has.Length.EqualTo(4));
            foreach (JsonElement shot in r)
            {
                // "inside" the net's rectangle would mean the ball hit the net.
                Assert.That(Crossing(shot, "net").GetProperty("inside").GetBoolean(), Is.False, shot.GetProperty("name").GetString());
            }

            // Minimum angles over the net: the centre passes within 3 cm of the tape (0.914 m). 0.1 deg moves the
            // crossing height by 11.885 m x 0.1 deg = 2.1 cm, so 3 cm is ~0.15 deg, inside issue 3's 0.25 deg
            // allowance between Cross's angles and this model's.
            Assert.That(Crossing(r[0], "net").GetProperty("position")[2].GetDouble(), Is.EqualTo(0.914).Within(0.03));
            Assert.That(Crossing(r[2], "net").GetProperty("position")[2].GetDouble(), Is.EqualTo(0.914).Within(0.03));
            // Baseline angles: landing within 0.3 m of 23.77 m. Measured here, 0.1 deg moves the landing by 0.14 m
            // (8.1 deg) and 0.10 m (11.9 deg), so 0.3 m is ~0.2-0.3 deg: issue 3's 0.25 deg allowance.
            Assert.That(r[1].GetProperty("landing").GetProperty("position")[0].GetDouble(), Is.EqualTo(23.77).Within(0.3));
            Assert.That(r[3].GetProperty("landing").GetProperty("position")[0].GetDouble(), Is.EqualTo(23.77).Within(0.3));
        }

        [Test]
        public void FreeKicks_OnlyTheMiddleSpeedScores()
        {
            JsonElement[] r = Results("samples/scenarios/freekicks.json");
            Assert.That(r, Has.Length.EqualTo(3));
            // 19.32 m/s: on the ground before the goal line.
            Assert.That(r[0].GetProperty("crossings").EnumerateArray().Any(c => c.GetProperty("name").GetString() == "goal"), Is.False);
            Assert.That(r[0].GetProperty("landing").GetProperty("position")[0].GetDouble(), Is.LessThan(20));
            // 24.15 m/s: through the target (3.2 m to the side, 2.2 m high) to the 1 cm the launch angles were solved to, inside the goal.
            JsonElement goal = Crossing(r[1], "goal");
            Assert.That(goal.GetProperty("inside").GetBoolean(), Is.True);
            Assert.That(goal.GetProperty("position")[1].GetDouble(), Is.EqualTo(3.2).Within(0.01));
            Assert.That(goal.GetProperty("position")[2].GetDouble(), Is.EqualTo(2.2).Within(0.01));
            // 28.91 m/s: over the crossbar.
            JsonElement over = Crossing(r[2], "goal");
            Assert.That(over.GetProperty("inside").GetBoolean(), Is.False);
            Assert.That(over.GetProperty("position")[2].GetDouble(), Is.GreaterThan(2.44));
        }
    }
}
