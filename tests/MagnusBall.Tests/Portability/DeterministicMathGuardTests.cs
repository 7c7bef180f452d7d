using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace MagnusBall.Tests.Portability
{
    /// <summary>
    /// Lockstep games need the same bits on every player's machine; Math's transcendentals come from each
    /// platform's C library or JIT and do not promise that (docs/determinism.md). The library therefore calls
    /// only PortableMath for them. This scans the library's source, so a new law or query that calls Math.Exp,
    /// Math.Pow, ... fails here.
    /// </summary>
    public class DeterministicMathGuardTests
    {
        /// <summary>The System.Math (and MathF) functions whose results differ between platforms. Sqrt, Abs, Floor, Min, Max, ... are exact and allowed.</summary>
        private static readonly Regex Forbidden = new Regex(
            @"\bMathF?\s*\.\s*(Sin|Cos|Tan|Atan|Atan2|Asin|Acos|Exp|Log|Log10|Log2|Pow|Cbrt|Tanh|Sinh|Cosh|Asinh|Acosh|Atanh|SinCos|ScaleB|FusedMultiplyAdd)\s*\(");

        [Test]
        public void Library_CallsNoPlatformTranscendental()
        {
            string runtime = Path.Combine(RepositoryRoot(), "src", "MagnusBall", "Runtime");
            var offenders = new List<string>();
            int files = 0;
            foreach (string file in Directory.GetFiles(runtime, "*.cs", SearchOption.AllDirectories))
            {
                if (Path.GetFileName(file) == "PortableMath.cs")
                {
                    continue; // the implementation: its docs name what it replaces
                }

                files++;
                string[] lines = File.ReadAllLines(file);
                for (int i = 0; i < lines.Length; i++)
                {
                    string code = StripComment(lines[i]);
                    Match match = Forbidden.Match(code);
                    if (match.Success)
                    {
                        offenders.Add($"{file.Substring(runtime.Length + 1)}:{i + 1}: {match.Value}");
                    }
                }
            }

            Assert.That(files, Is.GreaterThan(30), "the scan must read the library's sources");
            Assert.That(offenders, Is.Empty,
                "call MagnusBall.PortableMath (Sin, Cos, Atan, Atan2, Exp, Log, Pow) instead of System.Math's transcendentals, whose " +
                "results differ between platforms and runtimes (docs/determinism.md); add a missing function to PortableMath with a sweep test:\n" +
                string.Join("\n", offenders));
        }

        [TestCase("x = Math.Pow(a, b);", true)]
        [TestCase("x = System.Math.Exp (a);", true)]
        [TestCase("x = MathF.Sin(a);", true)]
        [TestCase("x = Math.Sqrt(a) + Math.Abs(b);", false)]
        [TestCase("x = PortableMath.Pow(a, b); // not Math.Pow(a, b)", false)]
        public void TheScan_TellsAPlatformCallFromAnAllowedOne(string line, bool forbidden)
        {
            Assert.That(Forbidden.IsMatch(StripComment(line)), Is.EqualTo(forbidden));
        }

        private static string StripComment(string line)
        {
            int comment = line.IndexOf("//", StringComparison.Ordinal);
            return comment < 0 ? line : line.Substring(0, comment);
        }

        private static string RepositoryRoot()
        {
            for (DirectoryInfo? dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); dir != null; dir = dir.Parent)
            {
                if (File.Exists(Path.Combine(dir.FullName, "MagnusBall.sln")))
                {
                    return dir.FullName;
                }
            }

            throw new InvalidOperationException("MagnusBall.sln not found above " + TestContext.CurrentContext.TestDirectory);
        }
    }
}
