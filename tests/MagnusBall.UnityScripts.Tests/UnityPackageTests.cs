using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// src/MagnusBall is also a Unity package (added by git URL with ?path=src/MagnusBall): its manifest,
    /// assembly definition and .meta files must be what Unity's package manager expects.
    /// </summary>
    [TestFixture]
    public class UnityPackageTests
    {
        private static readonly string Package = Path.Combine(RepositoryRoot(), "src", "MagnusBall");

        private static string RepositoryRoot()
        {
            for (var directory = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); directory != null; directory = directory.Parent)
            {
                if (File.Exists(Path.Combine(directory.FullName, "MagnusBall.sln")))
                {
                    return directory.FullName;
                }
            }

            throw new InvalidOperationException("MagnusBall.sln not found above the test directory");
        }

        [Test]
        public void TheManifest_NamesThePackage_AndKeepsTheLibrarysVersion()
        {
            using JsonDocument manifest = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "package.json")));
            JsonElement root = manifest.RootElement;
            // Unity: lower-case reverse-domain name, at most 214 characters.
            Assert.That(root.GetProperty("name").GetString(), Does.Match("^[a-z0-9-]+(\\.[a-z0-9-]+){2,}$"));
            Assert.That(root.GetProperty("displayName").GetString(), Is.EqualTo("MagnusBall"));
            // C# 9 on .NET Standard 2.1 needs Unity 2021.2 or later.
            Assert.That(root.GetProperty("unity").GetString(), Is.EqualTo("2021.2"));

            string csproj = File.ReadAllText(Path.Combine(Package, "MagnusBall.csproj"));
            string version = Regex.Match(csproj, "<Version>([^<]+)</Version>").Groups[1].Value;
            Assert.That(root.GetProperty("version").GetString(), Is.EqualTo(version), "package.json and MagnusBall.csproj give the same version");
        }

        [Test]
        public void TheAssemblyDefinition_IsEngineFree_AndAutoReferenced()
        {
            using JsonDocument asmdef = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "MagnusBall.asmdef")));
            JsonElement root = asmdef.RootElement;
            Assert.That(root.GetProperty("name").GetString(), Is.EqualTo("MagnusBall"));
            Assert.That(root.GetProperty("noEngineReferences").GetBoolean(), Is.True, "the library uses no UnityEngine type");
            Assert.That(root.GetProperty("autoReferenced").GetBoolean(), Is.True, "scripts in Assets see it without an asmdef of their own");
            Assert.That(root.GetProperty("references").GetArrayLength(), Is.EqualTo(0));
        }

        [Test]
        public void EveryAsset_HasAMetaFile_WithAUniqueGuid()
        {
            var assets = Directory.EnumerateFileSystemEntries(Package, "*", SearchOption.AllDirectories)
                .Where(p => !p.EndsWith(".meta", StringComparison.Ordinal))
                .Where(p => !IsBuildOutput(p))
                .ToList();
            List<string> missing = assets.Where(p => !File.Exists(p + ".meta")).Select(p => Path.GetRelativePath(Package, p)).ToList();
            if (missing.Count > 0)
            {
                // A warning, not a failure: a file merged without its .meta still builds everywhere but Unity,
                // which skips it in a git package. The fix is one command.
                Assert.Warn($"Unity will ignore {missing.Count} file(s) of the git package until they have a .meta " +
                            $"(run bash samples/TennisScene/tools/write-unity-meta.sh): {string.Join(", ", missing)}");
            }

            var guids = Directory.EnumerateFiles(Package, "*.meta", SearchOption.AllDirectories)
                .Where(p => !IsBuildOutput(p))
                .Select(p => Regex.Match(File.ReadAllText(p), "^guid: ([0-9a-f]{32})$", RegexOptions.Multiline).Groups[1].Value)
                .ToList();
            Assert.That(guids, Has.None.Empty, "every .meta has a 32-digit guid");
            Assert.That(guids, Is.Unique);
            Assert.That(guids.Count, Is.GreaterThan(10));
        }

        private static bool IsBuildOutput(string path)
        {
            string relative = Path.GetRelativePath(Package, path).Replace('\\', '/');
            return relative == "bin" || relative == "obj" || relative.StartsWith("bin/", StringComparison.Ordinal) || relative.StartsWith("obj/", StringComparison.Ordinal);
        }
    }
}
