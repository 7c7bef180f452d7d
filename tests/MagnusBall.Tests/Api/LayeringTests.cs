using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using MagnusBall.Tests.Contact;
using NUnit.Framework;

namespace MagnusBall.Tests.Api
{
    /// <summary>
    /// The layers of docs/architecture.md, read from the sources: physics (MagnusBall, Aerodynamics, Contact and its
    /// Swings, Presets), then integration (Integration and its Kernels), then flight (Flight), then the clients (Queries,
    /// Stepping, Batch, Shots). A file may name its own layer and those below, never one above: not in a using directive,
    /// not in a qualified name, not in a cref (prose in comments may mention any layer). The Unity components (Runtime/Unity) are a client assembly of their own.
    /// </summary>
    public class LayeringTests
    {
        private static readonly Dictionary<string, int> LayerOf = new Dictionary<string, int>
        {
            ["MagnusBall"] = 0, ["MagnusBall.Aerodynamics"] = 0, ["MagnusBall.Contact"] = 0, ["MagnusBall.Contact.Swings"] = 0, ["MagnusBall.Contact.Shapes"] = 0,
            ["MagnusBall.Presets"] = 0,
            ["MagnusBall.Integration"] = 1, ["MagnusBall.Integration.Kernels"] = 1,
            ["MagnusBall.Flight"] = 2,
            ["MagnusBall.Queries"] = 3, ["MagnusBall.Stepping"] = 3, ["MagnusBall.Batch"] = 3, ["MagnusBall.Shots"] = 3,
        };

        private static readonly string[] Names = { "physics", "integration", "flight", "clients" };

        [Test]
        public void NoFile_NamesALayerAboveItsOwn()
        {
            string runtime = Path.Combine(BounceFigure.RepositoryRoot(), "src", "MagnusBall", "Runtime");
            var upward = new List<string>();
            int files = 0;
            foreach (string file in Directory.EnumerateFiles(runtime, "*.cs", SearchOption.AllDirectories))
            {
                string relative = Path.GetRelativePath(runtime, file).Replace('\\', '/');
                if (relative.StartsWith("Unity/"))
                {
                    continue;
                }

                string text = File.ReadAllText(file);
                Match ns = Regex.Match(text, @"^namespace\s+([\w.]+)", RegexOptions.Multiline);
                if (!ns.Success || !ns.Groups[1].Value.StartsWith("MagnusBall"))
                {
                    continue; // a compiler attribute in System's namespace (SkipLocalsInit.cs)
                }

                Assert.That(LayerOf.ContainsKey(ns.Groups[1].Value), Is.True, $"{relative}: a namespace of a known layer");
                int own = LayerOf[ns.Groups[1].Value];
                files++;
                foreach (string line in text.Split('\n'))
                {
                    // Comments may mention any layer in prose; in XML docs only a cref is a reference.
                    string code = Regex.IsMatch(line, @"^\s*///")
                        ? string.Join(" ", Regex.Matches(line, "cref=\"([^\"]*)\"").Select(m => m.Groups[1].Value))
                        : Regex.Replace(line, @"^\s*//.*$", "");
                    foreach (KeyValuePair<string, int> layer in LayerOf.Where(l => l.Value > own))
                    {
                        string name = layer.Key.Substring("MagnusBall.".Length);
                        // using MagnusBall.X; MagnusBall.X.Type; or X.Type written from inside the MagnusBall namespace.
                        if (Regex.IsMatch(code, $@"(\bMagnusBall\.{Regex.Escape(name)}\b(?!\.\w+\s*=)|(?<![\w.]){Regex.Escape(name)}\.[A-Z])"))
                        {
                            upward.Add($"{relative} ({Names[own]}) names {layer.Key} ({Names[layer.Value]}): {line.Trim()}");
                        }
                    }
                }
            }

            Assert.That(files, Is.GreaterThan(50));
            Assert.That(upward, Is.Empty);
        }
    }
}
