using System;
using System.Linq;
using MagnusBall.Fuzz;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests.Fuzz
{
    /// <summary>
    /// Issue 15's fuzz test: 400 seeded hostile scenario files through Program.Run (plain, --svg, --samples, --csv):
    /// exit 0 with valid JSON/CSV/SVG or exit 2 with one error line, never a crash, each run bounded. The long run
    /// (10,000 files) is `dotnet run -c Release --project benchmarks/MagnusBall.Benchmarks -- fuzz`.
    /// </summary>
    [TestFixture]
    public class CliFuzzTests
    {
        [Test]
        public void HostileFiles_ExitWith0Or2_WithValidOutput_InBoundedTime()
        {
            const int Files = 400;
            var generator = new HostileJson(seed: 15);
            int[] counts = new int[Enum.GetValues<CliOutcome>().Length];
            TimeSpan slowest = TimeSpan.Zero;
            long saved = ScenarioFlight.EvaluationsPerFileLimit;
            ScenarioFlight.EvaluationsPerFileLimit = 800_000; // the cap's own path, at a size that keeps the suite fast
            try
            {
                for (int i = 0; i < Files; i++)
                {
                    string json = generator.Next();
                    (CliOutcome outcome, string detail, TimeSpan time) = CliFuzz.Run(json, i);
                    counts[(int)outcome]++;
                    slowest = time > slowest ? time : slowest;
                    Assert.That(outcome, Is.EqualTo(CliOutcome.Success).Or.EqualTo(CliOutcome.InputError), $"file {i}: {detail}\n{json}");
                    // 10 s: the hang threshold; files here take milliseconds (at most 1e5 steps kept, 8e5 model evaluations a file).
                    Assert.That(time.TotalSeconds, Is.LessThan(10), $"file {i} ran {time.TotalSeconds:F1} s\n{json}");
                }
            }
            finally
            {
                ScenarioFlight.EvaluationsPerFileLimit = saved;
            }

            TestContext.Out.WriteLine($"{Files} files: " + string.Join(", ", Enum.GetValues<CliOutcome>().Select(o => $"{o} {counts[(int)o]}")) +
                                      $"; slowest {slowest.TotalMilliseconds:F0} ms");
            // Both outcomes must really occur, or the generator tests nothing.
            Assert.That(counts[(int)CliOutcome.Success], Is.GreaterThan(Files / 20));
            Assert.That(counts[(int)CliOutcome.InputError], Is.GreaterThan(Files / 20));
        }
    }
}
