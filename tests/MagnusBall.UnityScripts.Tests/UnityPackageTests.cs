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

            string csproj = File.ReadAllText(Path.Combine(Package, "Runtime", "MagnusBall.csproj"));
            string version = Regex.Match(csproj, "<Version>([^<]+)</Version>").Groups[1].Value;
            Assert.That(root.GetProperty("version").GetString(), Is.EqualTo(version), "package.json and MagnusBall.csproj give the same version");
        }

        [Test]
        public void TheManifest_DeclaresEveryUnityModuleTheComponentsUse()
        {
            // MagnusBallRigidbody uses Rigidbody, Collision and ForceMode: the Physics module's types. A project that
            // disabled the module would not compile the package unless the manifest pulls the module in.
            using JsonDocument manifest = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "package.json")));
            JsonElement dependencies = manifest.RootElement.GetProperty("dependencies");
            string components = string.Concat(Directory.EnumerateFiles(Path.Combine(Package, "Runtime", "Unity"), "*.cs").Select(File.ReadAllText));
            Assert.That(components, Does.Contain("Rigidbody").And.Contain("ForceMode"), "the premise: the components use physics");
            Assert.That(dependencies.GetProperty("com.unity.modules.physics").GetString(), Is.EqualTo("1.0.0"));
        }

        [Test]
        public void TheAssemblyDefinition_IsEngineFree_AndAutoReferenced()
        {
            using JsonDocument asmdef = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "Runtime", "MagnusBall.asmdef")));
            JsonElement root = asmdef.RootElement;
            Assert.That(root.GetProperty("name").GetString(), Is.EqualTo("MagnusBall"));
            Assert.That(root.GetProperty("noEngineReferences").GetBoolean(), Is.True, "the library uses no UnityEngine type");
            Assert.That(root.GetProperty("autoReferenced").GetBoolean(), Is.True, "scripts in Assets see it without an asmdef of their own");
            Assert.That(root.GetProperty("references").GetArrayLength(), Is.EqualTo(0));
        }

        [Test]
        public void TheComponentsAssemblyDefinition_ReferencesTheCore_WithEngineReferences()
        {
            using JsonDocument asmdef = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "Runtime", "Unity", "MagnusBall.Unity.asmdef")));
            JsonElement root = asmdef.RootElement;
            Assert.That(root.GetProperty("name").GetString(), Is.EqualTo("MagnusBall.Unity"));
            Assert.That(root.GetProperty("noEngineReferences").GetBoolean(), Is.False, "the components use UnityEngine");
            Assert.That(root.GetProperty("autoReferenced").GetBoolean(), Is.True);
            Assert.That(root.GetProperty("references").EnumerateArray().Select(r => r.GetString()), Is.EqualTo(new[] { "MagnusBall" }));

            // The engine-free core must not compile the components (they need UnityEngine).
            string csproj = File.ReadAllText(Path.Combine(Package, "Runtime", "MagnusBall.csproj"));
            Assert.That(csproj, Does.Contain("<Compile Remove=\"Unity/**\" />"));
        }

        [Test]
        public void EveryAsset_HasAMetaFile_WithAUniqueGuid()
        {
            var assets = Directory.EnumerateFileSystemEntries(Package, "*", SearchOption.AllDirectories)
                .Where(p => !p.EndsWith(".meta", StringComparison.Ordinal))
                .Where(p => !IsNotImported(p))
                .ToList();
            List<string> missing = assets.Where(p => !File.Exists(p + ".meta")).Select(p => Path.GetRelativePath(Package, p)).ToList();
            if (missing.Count > 0)
            {
                // A warning, not a failure: a file merged without its .meta still builds everywhere but Unity,
                // which skips it in a git package. The fix is one command.
                Assert.Warn($"Unity will ignore {missing.Count} file(s) of the git package until they have a .meta " +
                            $"(run bash tools/write-unity-meta.sh): {string.Join(", ", missing)}");
            }

            var guids = Directory.EnumerateFiles(Package, "*.meta", SearchOption.AllDirectories)
                .Where(p => !IsNotImported(p))
                .Select(p => Regex.Match(File.ReadAllText(p), "^guid: ([0-9a-f]{32})$", RegexOptions.Multiline).Groups[1].Value)
                .ToList();
            Assert.That(guids, Has.None.Empty, "every .meta has a 32-digit guid");
            Assert.That(guids, Is.Unique);
            Assert.That(guids.Count, Is.GreaterThan(10));
        }

        [Test]
        public void NoBuildOutput_InsideThePackage()
        {
            // This test runs after the solution was built: Directory.Build.props must have sent every bin/ and
            // obj/ to artifacts/. A bin/ or obj/ in the package makes Unity compile AssemblyInfo twice (CS0579).
            var output = Directory.EnumerateDirectories(Package, "*", SearchOption.AllDirectories)
                .Select(d => Path.GetFileName(d))
                .Where(name => name == "bin" || name == "obj")
                .ToList();
            Assert.That(output, Is.Empty, "no bin/ or obj/ under src/MagnusBall");
        }

        [Test]
        public void ThePackage_HasEveryPartUnitysLayoutNames()
        {
            foreach (string part in new[] { "package.json", "README.md", "CHANGELOG.md", "LICENSE.md" })
            {
                Assert.That(File.Exists(Path.Combine(Package, part)), Is.True, part);
            }

            foreach (string part in new[] { "Runtime", "Samples~", "Tests/Runtime", "Documentation~" })
            {
                Assert.That(Directory.Exists(Path.Combine(Package, part)), Is.True, part);
                Assert.That(Directory.EnumerateFiles(Path.Combine(Package, part), "*", SearchOption.AllDirectories), Is.Not.Empty, part + " is not empty");
            }

            Assert.That(File.ReadAllText(Path.Combine(Package, "LICENSE.md")), Does.StartWith("MIT License").And.Contains("the MagnusBall project"));
            Assert.That(File.ReadAllText(Path.Combine(RepositoryRoot(), "LICENSE")), Is.EqualTo(File.ReadAllText(Path.Combine(Package, "LICENSE.md"))));
        }

        [Test]
        public void TheManifest_DeclaresTheSample_AndItsLinks()
        {
            using JsonDocument manifest = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "package.json")));
            JsonElement root = manifest.RootElement;
            JsonElement[] samples = root.GetProperty("samples").EnumerateArray().ToArray();
            Assert.That(samples, Has.Length.GreaterThanOrEqualTo(1));
            foreach (JsonElement sample in samples)
            {
                string path = sample.GetProperty("path").GetString()!;
                Assert.That(path, Does.StartWith("Samples~/"), "Unity imports samples from Samples~");
                Assert.That(Directory.EnumerateFiles(Path.Combine(Package, path), "*.cs", SearchOption.AllDirectories), Is.Not.Empty, path);
                Assert.That(sample.GetProperty("displayName").GetString(), Is.Not.Empty);
            }

            foreach (string url in new[] { "documentationUrl", "changelogUrl", "licensesUrl" })
            {
                string value = root.GetProperty(url).GetString()!;
                Assert.That(value, Does.StartWith("https://"), url);
                // Each link names a file of this package: that file must exist.
                string file = value.Substring(value.IndexOf("/src/MagnusBall/", StringComparison.Ordinal) + "/src/MagnusBall/".Length);
                Assert.That(File.Exists(Path.Combine(Package, file)), Is.True, url + " -> " + file);
            }
        }

        [Test]
        public void TheTestAssemblyDefinition_IsAUnityTestFrameworkAssembly()
        {
            using JsonDocument asmdef = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "Tests", "Runtime", "MagnusBall.Tests.Runtime.asmdef")));
            JsonElement root = asmdef.RootElement;
            string[] references = root.GetProperty("references").EnumerateArray().Select(e => e.GetString()!).ToArray();
            Assert.That(references, Does.Contain("MagnusBall").And.Contain("UnityEngine.TestRunner"));
            Assert.That(root.GetProperty("precompiledReferences").EnumerateArray().Select(e => e.GetString()), Does.Contain("nunit.framework.dll"));
            Assert.That(root.GetProperty("defineConstraints").EnumerateArray().Select(e => e.GetString()), Does.Contain("UNITY_INCLUDE_TESTS"));
        }

        [Test]
        public void TheEditModeTestAssembly_IsEditorOnly_AndSeesTheComponents()
        {
            using JsonDocument asmdef = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "Tests", "Editor", "MagnusBall.Tests.Editor.asmdef")));
            JsonElement root = asmdef.RootElement;
            Assert.That(root.GetProperty("includePlatforms").EnumerateArray().Select(e => e.GetString()), Is.EqualTo(new[] { "Editor" }), "Edit Mode");
            string[] references = root.GetProperty("references").EnumerateArray().Select(e => e.GetString()!).ToArray();
            Assert.That(references, Does.Contain("MagnusBall").And.Contain("MagnusBall.Unity").And.Contain("UnityEngine.TestRunner").And.Contain("UnityEditor.TestRunner"));
            Assert.That(root.GetProperty("precompiledReferences").EnumerateArray().Select(e => e.GetString()), Does.Contain("nunit.framework.dll"));
            Assert.That(root.GetProperty("defineConstraints").EnumerateArray().Select(e => e.GetString()), Does.Contain("UNITY_INCLUDE_TESTS"));
            Assert.That(root.GetProperty("autoReferenced").GetBoolean(), Is.False);
            Assert.That(Directory.EnumerateFiles(Path.Combine(Package, "Tests", "Editor"), "*.cs"), Is.Not.Empty);
        }

        private static bool IsNotImported(string path)
        {
            // Folders whose name ends in "~" (Samples~, Documentation~) are not imported by Unity: no .meta there.
            string relative = Path.GetRelativePath(Package, path).Replace('\\', '/');
            return relative.Split('/').Any(part => part.EndsWith("~", StringComparison.Ordinal));
        }
    }
}
