using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>The headless tennis scene (README's main job) as a process: its table, its picture and its errors.</summary>
    [TestFixture]
    public class HeadlessRunnerTests
    {
        private static (int ExitCode, string Output, string Error) Run(params string[] args)
        {
            // artifacts/bin/MagnusBall.UnityScripts.Tests/<configuration> -> artifacts/bin/TennisScene.Headless/<configuration>
            // (Directory.Build.props puts every project's output under artifacts/).
            var here = new DirectoryInfo(TestContext.CurrentContext.TestDirectory);
            string dll = Path.Combine(here.Parent!.Parent!.FullName, "TennisScene.Headless", here.Name, "TennisScene.Headless.dll");
            Assert.That(File.Exists(dll), Is.True, dll);

            var start = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
            {
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                UseShellExecute = false,
            };
            start.ArgumentList.Add(dll);
            foreach (string arg in args)
            {
                start.ArgumentList.Add(arg);
            }

            using Process process = Process.Start(start)!;
            string output = process.StandardOutput.ReadToEnd();
            string error = process.StandardError.ReadToEnd();
            process.WaitForExit();
            return (process.ExitCode, output, error);
        }

        [Test]
        public void TheSixShots_AllLandIn_AndThePictureIsWritten()
        {
            string svg = Path.Combine(Path.GetTempPath(), $"tennis-scene-{Guid.NewGuid():N}.svg");
            try
            {
                (int code, string output, string error) = Run("--svg", svg);
                TestContext.Out.WriteLine(output);
                Assert.That(code, Is.EqualTo(0), error);
                string[] rows = output.Split('\n');
                foreach (string shot in new[] { "flat serve", "kick serve", "topspin forehand", "slice backhand", "topspin lob", "drop shot" })
                {
                    string row = rows.Single(r => r.StartsWith(shot, StringComparison.Ordinal));
                    Assert.That(row.Split(' ', StringSplitOptions.RemoveEmptyEntries), Does.Contain("in"), row);
                }

                Assert.That(output, Does.Contain("picture: " + svg));
                string picture = File.ReadAllText(svg);
                Assert.That(picture, Does.StartWith("<svg"));
                Assert.That(picture.Split("<polyline").Length - 1, Is.EqualTo(14), "six shots and the let in two views");
            }
            finally
            {
                File.Delete(svg);
            }
        }

        [Test]
        public void TheNetCordLet_ClipsTheTape_AndDropsInTheServiceBox_InTheTableAndThePicture()
        {
            // Issue 40, item 6b: the scene's net is SportShapes.TennisNet; the let's serve touches the cord (a Contact event)
            // and lands in the far deuce service box.
            string svg = Path.Combine(Path.GetTempPath(), $"tennis-scene-{Guid.NewGuid():N}.svg");
            try
            {
                (int code, string output, string error) = Run("--svg", svg);
                Assert.That(code, Is.EqualTo(0), error);
                string row = output.Split('\n').Single(r => r.StartsWith("net-cord let", StringComparison.Ordinal));
                string[] cells = row.Split(' ', StringSplitOptions.RemoveEmptyEntries);
                Assert.That(cells, Does.Contain("cord"), row);
                Assert.That(cells, Does.Contain("LET"), row);
                string picture = File.ReadAllText(svg);
                Assert.That(picture, Does.Contain("a LET (clipped the cord, in the box)"));
                Assert.That(picture.Split("<polygon").Length - 1, Is.EqualTo(2), "the touch of the cord, a diamond in each view");
            }
            finally
            {
                File.Delete(svg);
            }

            var simulation = new MagnusBall.Samples.TennisScene.ShotSimulation(new MagnusBall.Samples.TennisScene.SceneSettings());
            MagnusBall.Samples.TennisScene.ShotReport report = simulation.Run(MagnusBall.Samples.TennisScene.StandardShots.NetCordLet, Span<Vector3d>.Empty);
            Assert.That(report.IsLet, Is.True);
            Assert.That(report.NetContact.HasValue && MagnusBall.Samples.TennisScene.ShotSimulation.IsCord(report.NetContact.Value.ShapeId), Is.True);
            Assert.That(report.Landing.X, Is.InRange(0, MagnusBall.Samples.TennisScene.TennisCourt.ServiceLineFromNet));
            Assert.That(report.Landing.Z, Is.InRange(0, MagnusBall.Samples.TennisScene.TennisCourt.HalfSinglesWidth));
        }

        [Test]
        public void TheSwingTable_PrintsEachSwingNextToItsLaunch_AndBySwingFliesThem()
        {
            (int code, string output, string error) = Run("--no-svg");
            Assert.That(code, Is.EqualTo(0), error);
            string[] rows = output.Split('\n');
            foreach (string shot in new[] { "flat serve", "kick serve", "topspin forehand", "slice backhand", "topspin lob", "drop shot" })
            {
                // "  name  racket path face turn ACOR azim -> v elev azim top side landing in"
                string row = rows.Single(r => r.StartsWith("  " + shot, StringComparison.Ordinal));
                Assert.That(row, Does.Contain("->"), row);
                Assert.That(row.TrimEnd().EndsWith("in", StringComparison.Ordinal), Is.True, row);
            }

            (code, output, error) = Run("--by-swing", "--no-svg");
            Assert.That(code, Is.EqualTo(0), error);
            rows = output.Split('\n');
            foreach (string shot in new[] { "flat serve", "kick serve", "topspin forehand", "slice backhand", "topspin lob", "drop shot" })
            {
                string row = rows.Single(r => r.StartsWith(shot, StringComparison.Ordinal));
                Assert.That(row.Split(' ', StringSplitOptions.RemoveEmptyEntries), Does.Contain("in"), row);
            }

            (code, _, error) = Run("--by-swing", "--speed", "30", "--no-svg");
            Assert.That(code, Is.EqualTo(2));
            Assert.That(error, Does.Contain("--by-swing"));
        }

        [TestCase("--speed", "fast", "--speed must be a finite number")]
        [TestCase("--elevation", "95", "--elevation must be in [-89.9, 89.9]")]
        [TestCase("--shot", "smash", "--shot must be one of")]
        [TestCase("--integrator", "verlet", "--integrator must be one of")]
        [TestCase("--frobnicate", null, "unknown option '--frobnicate'")]
        [TestCase("--step", null, "--step needs a value")]
        [TestCase("--aim", "9.5", "--aim must be two finite numbers X,Z")]
        [TestCase("--aim", "60,0", "cannot be reached")]
        public void BadOptions_ExitWithCode2_AndSayWhatIsWrong(string option, string? value, string message)
        {
            (int code, string output, string error) = value == null ? Run(option, "--no-svg") : Run(option, value, "--no-svg");
            if (option == "--step")
            {
                (code, output, error) = Run("--no-svg", option);
            }

            Assert.That(code, Is.EqualTo(2));
            Assert.That(error, Does.Contain(message));
            Assert.That(error, Does.Not.Contain("(Parameter"), "the message names the option, not a library parameter");
            Assert.That(output, Is.Empty);
        }

        [TestCase("--speed", "0.1..120", "0.09", "[0.1, 120]")]
        [TestCase("--height", "0.05..10", "10.5", "[0.05, 10]")]
        [TestCase("--step", "1e-6..0.1", "0.2", "[1E-06, 0.1]")]
        [TestCase("--density", "0..5", "6", "[0, 5]")]
        [TestCase("--topspin", "-10000..10000", "12000", "[-10000, 10000]")]
        [TestCase("--z", "-10..10", "-11", "[-10, 10]")]
        public void Help_StatesTheRangeTheParserEnforces(string option, string helpRange, string outside, string errorRange)
        {
            (_, string help, _) = Run("--help");
            string line = help.Split('\n').Single(l => l.TrimStart().StartsWith(option + " ", StringComparison.Ordinal));
            Assert.That(line, Does.Contain("(" + helpRange), line);
            (int code, _, string error) = Run(option, outside, "--no-svg");
            Assert.That(code, Is.EqualTo(2));
            Assert.That(error, Does.Contain(option + " must be in " + errorRange));
        }

        [Test]
        public void Help_ListsEveryIntegrator_AndTheAnglesItAccepts()
        {
            (int code, string output, _) = Run("--help");
            Assert.That(code, Is.EqualTo(0));
            foreach (string name in MagnusBall.Integration.Integrators.Names)
            {
                Assert.That(output, Does.Contain(name), "every integrator the scene accepts is listed");
            }

            // The range the parser enforces (Program.cs: -89.9..89.9), not a wider one.
            Assert.That(output, Does.Contain("--elevation DEG     launch angle above horizontal (-89.9..89.9)"));
            (int bad, _, string error) = Run("--elevation", "90");
            Assert.That(bad, Is.EqualTo(2));
            Assert.That(error, Does.Contain("--elevation"));
        }

        [Test]
        public void Aim_SolvesTheAngles_SoTheBallLandsOnTheTarget()
        {
            // The kick serve's speed and spin (with sidespin, so the sidespin sign convention is exercised), aimed
            // at a point in the deuce box; the table prints the landing to the centimetre.
            (int code, string output, string error) = Run("--shot", "kick serve", "--aim", "5.5,3", "--no-svg");
            Assert.That(code, Is.EqualTo(0), error);
            string row = output.Split('\n').Single(r => r.StartsWith("kick serve* ", StringComparison.Ordinal)); // it named itself "custom shot"
            Assert.That(row, Does.Contain("  5.50,  3.00 in"), row);
        }

        [Test]
        public void AStandardShot_WithAnotherIntegrator_KeepsItsName()
        {
            // Only the options that change the shot make it a "custom shot"; the integrator and its step do not.
            (int code, string output, string error) = Run("--shot", "kick serve", "--integrator", "euler", "--step", "0.02", "--no-svg");
            Assert.That(code, Is.EqualTo(0), error);
            Assert.That(output.Split('\n').Count(r => r.StartsWith("kick serve", StringComparison.Ordinal)), Is.EqualTo(1), output);
            Assert.That(output, Does.Not.Contain("custom shot"));
        }

        [Test]
        public void OneCustomShot_IsOneRow()
        {
            (int code, string output, string error) = Run("--speed", "28", "--elevation", "10", "--topspin", "3000", "--no-svg");
            Assert.That(code, Is.EqualTo(0), error);
            Assert.That(output.Split('\n').Count(r => r.StartsWith("custom shot", StringComparison.Ordinal)), Is.EqualTo(1));
            Assert.That(output, Does.Not.Contain("picture:"));
        }
    }
}
