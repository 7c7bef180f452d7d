using System.IO;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests.Api
{
    /// <summary>Usage errors exit with 2 and print the usage; --help exits with 0.</summary>
    [TestFixture]
    public class UsageTests
    {
        [TestCase(new string[0], "missing command", TestName = "Usage_NoArguments")]
        [TestCase(new[] { "simulat", "x.json" }, "unknown command 'simulat'", TestName = "Usage_UnknownCommand")]
        [TestCase(new[] { "simulate" }, "simulate needs a scenario FILE", TestName = "Usage_MissingFile")]
        [TestCase(new[] { "simulate", "a.json", "b.json" }, "simulate takes one FILE", TestName = "Usage_TwoFiles")]
        [TestCase(new[] { "simulate", "-", "--cvs" }, "unknown option '--cvs'", TestName = "Usage_UnknownOption")]
        [TestCase(new[] { "simulate", "-", "--samples" }, "--samples needs a value", TestName = "Usage_SamplesWithoutValue")]
        [TestCase(new[] { "simulate", "-", "--samples", "1" }, "--samples must be a whole number from 2", TestName = "Usage_SamplesTooFew")]
        [TestCase(new[] { "simulate", "-", "--samples", "ten" }, "--samples must be a whole number from 2", TestName = "Usage_SamplesNotANumber")]
        [TestCase(new[] { "simulate", "-", "--svg" }, "--svg needs a value", TestName = "Usage_SvgWithoutValue")]
        [TestCase(new[] { "simulate", "-", "--svg", "x.svg", "--svg-view", "front" }, "--svg-view must be side, top or both; got 'front'", TestName = "Usage_BadSvgView")]
        [TestCase(new[] { "simulate", "/no/such/file.json" }, "cannot read '/no/such/file.json': no such file", TestName = "Usage_MissingInputFile")]
        [TestCase(new[] { "aim" }, "aim takes exactly one FILE", TestName = "Usage_AimWithoutFile")]
        public void UsageError_ExitsWithTwo(string[] args, string expected)
        {
            CliRun run = CliRun.Of(args);
            Assert.Multiple(() =>
            {
                Assert.That(run.ExitCode, Is.EqualTo(2));
                Assert.That(run.Stderr, Does.StartWith("magnusball: " + expected));
                Assert.That(run.Stderr, Does.Contain("usage:"));
                Assert.That(run.Stdout, Is.Empty);
            });
        }

        [Test]
        public void Help_PrintsUsage_AndExitsWithZero()
        {
            CliRun run = CliRun.Of("--help");
            Assert.That(run.ExitCode, Is.EqualTo(0));
            Assert.That(run.Stdout, Does.Contain("magnusball simulate FILE"));
        }

        [Test]
        public void SimulateReadsAFile()
        {
            string path = Path.Combine(Path.GetTempPath(), $"magnusball-{System.Guid.NewGuid():N}.json");
            File.WriteAllText(path, CliRun.DriveJson);
            try
            {
                CliRun run = CliRun.Of("simulate", path);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
                Assert.That(run.FirstResult().GetProperty("name").GetString(), Is.EqualTo("drive"));
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Test]
        public void UnwritableSvgPath_ExitsWithOne()
        {
            CliRun run = CliRun.Simulate(CliRun.DriveJson, "--svg", "/no/such/dir/out.svg");
            Assert.That(run.ExitCode, Is.EqualTo(1), run.Stderr);
            Assert.That(run.Stderr, Does.StartWith("magnusball: "));
        }
    }
}
