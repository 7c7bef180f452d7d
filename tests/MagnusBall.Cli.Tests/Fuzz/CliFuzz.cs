using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Xml.Linq;
using MagnusBall.Cli;

namespace MagnusBall.Fuzz
{
    /// <summary>What one hostile CLI run did.</summary>
    public enum CliOutcome
    {
        /// <summary>Exit 0 with valid output.</summary>
        Success,

        /// <summary>Exit 2: a one-line input error, nothing on stdout.</summary>
        InputError,

        /// <summary>Any other exit code, or an exception out of Program.Run (a crash).</summary>
        Crash,

        /// <summary>Exit 0 but the JSON, CSV or SVG does not parse, or holds a non-finite coordinate.</summary>
        InvalidOutput,

        /// <summary>Exit 2 with a stack trace, several lines, or something on stdout.</summary>
        BadError,
    }

    /// <summary>Runs one hostile file through the CLI's in-process entry point and judges the result.</summary>
    public static class CliFuzz
    {
        /// <summary>Runs `simulate -` on <paramref name="json"/>, with --svg, --samples or --csv by <paramref name="variant"/>.</summary>
        public static (CliOutcome Outcome, string Detail, TimeSpan Time) Run(string json, int variant)
        {
            string svg = Path.Combine(Path.GetTempPath(), $"magnusball-fuzz-{Guid.NewGuid():N}.svg");
            string[] args = (variant % 4) switch
            {
                0 => new[] { "simulate", "-" },
                1 => new[] { "simulate", "-", "--svg", svg },
                2 => new[] { "simulate", "-", "--samples", "17" },
                _ => new[] { "simulate", "-", "--csv" },
            };
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            var clock = Stopwatch.StartNew();
            int code;
            try
            {
                code = Program.Run(args, stdout, stderr, new StringReader(json));
            }
            catch (Exception e)
            {
                return (CliOutcome.Crash, e.GetType().Name + ": " + e.Message, clock.Elapsed);
            }

            TimeSpan time = clock.Elapsed;
            try
            {
                string error = stderr.ToString();
                if (code == Program.BadInput)
                {
                    bool oneLine = error.StartsWith("magnusball: ", StringComparison.Ordinal) && error.TrimEnd('\n').IndexOf('\n') < 0;
                    return (oneLine && stdout.ToString().Length == 0 ? CliOutcome.InputError : CliOutcome.BadError, error, time);
                }

                if (code != Program.Success)
                {
                    return (CliOutcome.Crash, $"exit {code}: {error}", time);
                }

                string output = stdout.ToString();
                if (variant % 4 == 3)
                {
                    string[] lines = output.TrimEnd('\n').Split('\n');
                    if (lines[0] != "scenario,time,x,y,z,vx,vy,vz,wx,wy,wz" || lines.Length < 2)
                    {
                        return (CliOutcome.InvalidOutput, "csv: " + lines[0], time);
                    }
                }
                else
                {
                    using JsonDocument document = JsonDocument.Parse(output);
                    if (document.RootElement.GetProperty("results").GetArrayLength() == 0)
                    {
                        return (CliOutcome.InvalidOutput, "no results", time);
                    }
                }

                if (variant % 4 == 1)
                {
                    string? bad = CheckSvg(XDocument.Load(svg));
                    if (bad != null)
                    {
                        return (CliOutcome.InvalidOutput, "svg: " + bad, time);
                    }
                }

                return (CliOutcome.Success, string.Empty, time);
            }
            catch (Exception e) when (e is JsonException or System.Xml.XmlException or IOException or InvalidOperationException or FormatException or IndexOutOfRangeException)
            {
                return (CliOutcome.InvalidOutput, e.GetType().Name + ": " + e.Message, time);
            }
            finally
            {
                File.Delete(svg);
            }
        }

        /// <summary>Null when every coordinate of the SVG is a finite number, else the first bad attribute.</summary>
        public static string? CheckSvg(XDocument svg)
        {
            foreach (XAttribute a in svg.Descendants().Attributes())
            {
                string name = a.Name.LocalName;
                if (name is "x" or "y" or "x1" or "x2" or "y1" or "y2" or "cx" or "cy" or "width" or "height")
                {
                    if (!IsFinite(a.Value))
                    {
                        return $"{name}=\"{a.Value}\"";
                    }
                }
                else if (name == "points" && a.Value.Split(' ', StringSplitOptions.RemoveEmptyEntries).SelectMany(p => p.Split(',')).Any(c => !IsFinite(c)))
                {
                    return "points";
                }
            }

            return null;
        }

        private static bool IsFinite(string text) =>
            double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) && double.IsFinite(v);
    }
}
