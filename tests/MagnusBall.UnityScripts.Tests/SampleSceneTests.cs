using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text.Json;
using System.Text.RegularExpressions;
using MagnusBall.Components;
using MagnusBall.Samples.TennisScene.Scripts;
using MagnusBall.UnityStubs;
using NUnit.Framework;
using UnityEngine;
using static MagnusBall.UnityScripts.Tests.UnityLoop;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// The Tennis Scene sample's scene file (Samples~/TennisScene/Scenes/TennisScene.unity), read as Unity reads it, without
    /// Unity: a Unity YAML file whose every reference resolves (a script to a .meta of this package with that guid, a
    /// built-in asset to a whitelisted fileID of Unity's built-in resources, a local object to a document of the file), whose
    /// GameObjects, components and transform hierarchy agree, and whose MonoBehaviours set only fields their scripts
    /// serialize. Also: every file and folder of the sample has a .meta, no two metas of the package share a guid, and
    /// TennisSceneBootstrap builds the same objects from code.
    /// </summary>
    [TestFixture]
    [NonParallelizable]
    public class SampleSceneTests
    {
        private static readonly string Package = Path.Combine(RepositoryRoot(), "src", "MagnusBall");
        private static readonly string Sample = Path.Combine(Package, "Samples~", "TennisScene");
        private static readonly string ScenePath = Path.Combine(Sample, "Scenes", "TennisScene.unity");

        // Unity's class IDs (docs.unity3d.com/Manual/ClassIDReference.html) of the objects a scene may hold here.
        private static readonly Dictionary<int, string> ClassIds = new Dictionary<int, string>
        {
            [1] = "GameObject", [4] = "Transform", [20] = "Camera", [23] = "MeshRenderer", [29] = "OcclusionCullingSettings",
            [33] = "MeshFilter", [81] = "AudioListener", [104] = "RenderSettings", [108] = "Light", [114] = "MonoBehaviour",
            [120] = "LineRenderer", [135] = "SphereCollider", [157] = "LightmapSettings", [196] = "NavMeshSettings",
        };

        // Unity's built-in assets the scene may name (they are in every editor, not in the package): the guid of the built-in
        // resources (e000...) and of the built-in extra resources (f000...), with the fileIDs used.
        private static readonly Dictionary<string, Dictionary<long, string>> BuiltIn = new Dictionary<string, Dictionary<long, string>>
        {
            ["0000000000000000e000000000000000"] = new Dictionary<long, string> { [10207] = "Sphere mesh", [10001] = "spot cookie (RenderSettings' default)" },
            ["0000000000000000f000000000000000"] = new Dictionary<long, string> { [10303] = "Default-Material", [10304] = "Default-Skybox" },
        };

        private static readonly Regex Reference = new Regex(@"\{fileID: (-?\d+)(?:, guid: ([0-9a-f]{32}), type: (\d+))?\}");

        private sealed class Doc
        {
            public int ClassId;
            public long FileId;
            public string Type = string.Empty;
            public string Body = string.Empty;

            public long Ref(string field)
            {
                Match m = Regex.Match(Body, "^  " + Regex.Escape(field) + @": \{fileID: (-?\d+)", RegexOptions.Multiline);
                return m.Success ? long.Parse(m.Groups[1].Value) : throw new AssertionException($"{Type} &{FileId} has no {field}");
            }

            public List<long> RefList(string field)
            {
                Match block = Regex.Match(Body, "^  " + Regex.Escape(field) + @":\s*\n((?:  - .*\n)*)", RegexOptions.Multiline);
                return block.Success ? Reference.Matches(block.Groups[1].Value).Select(m => long.Parse(m.Groups[1].Value)).ToList() : new List<long>();
            }

            public string Scalar(string field) => Regex.Match(Body, "^  " + Regex.Escape(field) + @": (.*)$", RegexOptions.Multiline).Groups[1].Value.Trim();
        }

        private static List<Doc> Docs()
        {
            string text = File.ReadAllText(ScenePath).Replace("\r\n", "\n");
            var starts = Regex.Matches(text, @"^--- !u!(\d+) &(\d+)\n(\w+):\n", RegexOptions.Multiline).ToList();
            Assert.That(starts, Is.Not.Empty);
            var docs = new List<Doc>();
            for (int i = 0; i < starts.Count; i++)
            {
                int end = i + 1 < starts.Count ? starts[i + 1].Index : text.Length;
                docs.Add(new Doc
                {
                    ClassId = int.Parse(starts[i].Groups[1].Value),
                    FileId = long.Parse(starts[i].Groups[2].Value),
                    Type = starts[i].Groups[3].Value,
                    Body = text.Substring(starts[i].Index + starts[i].Length, end - starts[i].Index - starts[i].Length),
                });
            }

            return docs;
        }

        // Every .meta of the package (Samples~ included), by guid.
        private static Dictionary<string, string> MetasByGuid()
        {
            var byGuid = new Dictionary<string, string>();
            foreach (string meta in Directory.EnumerateFiles(Package, "*.meta", SearchOption.AllDirectories))
            {
                string guid = Regex.Match(File.ReadAllText(meta), "^guid: ([0-9a-f]{32})$", RegexOptions.Multiline).Groups[1].Value;
                Assert.That(guid, Is.Not.Empty, meta);
                Assert.That(byGuid.TryAdd(guid, meta), Is.True, $"{meta} and {(byGuid.TryGetValue(guid, out string? other) ? other : "")} share guid {guid}");
            }

            return byGuid;
        }

        [Test]
        public void TheScene_IsUnityYaml_WithKnownClassIdsAndUniqueFileIds()
        {
            string text = File.ReadAllText(ScenePath);
            Assert.That(text, Does.StartWith("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!"));
            List<Doc> docs = Docs();
            Assert.That(Regex.Matches(text, "^--- ", RegexOptions.Multiline).Count, Is.EqualTo(docs.Count), "every document has a class id, a fileID and a type");
            foreach (Doc d in docs)
            {
                Assert.That(ClassIds.TryGetValue(d.ClassId, out string? type) ? type : "unknown class id " + d.ClassId, Is.EqualTo(d.Type), $"&{d.FileId}");
            }

            Assert.That(docs.Select(d => d.FileId), Is.Unique);
            foreach (int settings in new[] { 29, 104, 157, 196 })
            {
                Assert.That(docs.Count(d => d.ClassId == settings), Is.EqualTo(1), ClassIds[settings]);
            }
        }

        [Test]
        public void EveryReference_Resolves_InTheFile_InThePackage_OrToAWhitelistedBuiltIn()
        {
            List<Doc> docs = Docs();
            var local = new HashSet<long>(docs.Select(d => d.FileId));
            Dictionary<string, string> metas = MetasByGuid();
            int external = 0, scripts = 0;
            foreach (Doc d in docs)
            {
                foreach (Match m in Reference.Matches(d.Body))
                {
                    long fileId = long.Parse(m.Groups[1].Value);
                    string where = $"{d.Type} &{d.FileId}: {m.Value}";
                    if (!m.Groups[2].Success)
                    {
                        Assert.That(fileId == 0 || local.Contains(fileId), Is.True, where + " names no document of the file");
                        continue;
                    }

                    external++;
                    string guid = m.Groups[2].Value;
                    if (BuiltIn.TryGetValue(guid, out Dictionary<long, string>? assets))
                    {
                        Assert.That(assets.ContainsKey(fileId), Is.True, where + ": not a whitelisted built-in asset");
                        Assert.That(m.Groups[3].Value, Is.EqualTo("0"), where + ": built-in assets are type 0");
                        continue;
                    }

                    Assert.That(metas.TryGetValue(guid, out string? meta), Is.True, where + ": no .meta of the package has this guid");
                    Assert.That(fileId, Is.EqualTo(11500000), where + ": a script's main object");
                    Assert.That(m.Groups[3].Value, Is.EqualTo("3"), where);
                    string script = meta!.Substring(0, meta.Length - ".meta".Length);
                    Assert.That(script, Does.EndWith(".cs"), where);
                    Assert.That(File.ReadAllText(meta), Does.Contain("MonoImporter:"), where);
                    // Unity finds a MonoBehaviour in a script by the file's name.
                    Assert.That(File.ReadAllText(script), Does.Match(@"class " + Path.GetFileNameWithoutExtension(script) + @"\s*:\s*MonoBehaviour"), where);
                    scripts++;
                }
            }

            Assert.That(external, Is.GreaterThan(scripts), "built-ins are referenced too (the sphere, the default material)");
            Assert.That(scripts, Is.EqualTo(docs.Count(d => d.ClassId == 114)), "every MonoBehaviour names its script");
        }

        [Test]
        public void GameObjects_AndTheirComponents_PointAtEachOther()
        {
            List<Doc> docs = Docs();
            Dictionary<long, Doc> byId = docs.ToDictionary(d => d.FileId);
            List<Doc> objects = docs.Where(d => d.ClassId == 1).ToList();
            Assert.That(objects, Has.Count.GreaterThanOrEqualTo(6));
            foreach (Doc go in objects)
            {
                List<long> components = go.RefList("m_Component");
                Assert.That(components, Is.Not.Empty.And.Unique, go.Scalar("m_Name"));
                Assert.That(byId[components[0]].ClassId, Is.EqualTo(4), go.Scalar("m_Name") + ": the first component is its Transform");
                Assert.That(components.Count(c => byId[c].ClassId == 4), Is.EqualTo(1), go.Scalar("m_Name") + ": one Transform");
                foreach (long c in components)
                {
                    Assert.That(byId.ContainsKey(c), Is.True, $"{go.Scalar("m_Name")}: component {c} exists");
                    Assert.That(byId[c].ClassId, Is.Not.EqualTo(1));
                    Assert.That(byId[c].Ref("m_GameObject"), Is.EqualTo(go.FileId), $"{go.Scalar("m_Name")}: {byId[c].Type} &{c} points back");
                }
            }

            foreach (Doc component in docs.Where(d => d.Body.Contains("\n  m_GameObject: ") || d.Body.StartsWith("  m_GameObject: ", StringComparison.Ordinal) || Regex.IsMatch(d.Body, "^  m_GameObject: ", RegexOptions.Multiline)))
            {
                long owner = component.Ref("m_GameObject");
                Assert.That(byId.TryGetValue(owner, out Doc? go) && go.ClassId == 1, Is.True, $"{component.Type} &{component.FileId}: its GameObject exists");
                Assert.That(go!.RefList("m_Component"), Does.Contain(component.FileId), $"{component.Type} &{component.FileId} is listed by its GameObject");
            }
        }

        [Test]
        public void Transforms_FathersAndChildren_Agree()
        {
            List<Doc> docs = Docs();
            Dictionary<long, Doc> byId = docs.ToDictionary(d => d.FileId);
            List<Doc> transforms = docs.Where(d => d.ClassId == 4).ToList();
            foreach (Doc t in transforms)
            {
                long father = t.Ref("m_Father");
                if (father != 0)
                {
                    Assert.That(byId.TryGetValue(father, out Doc? f) && f.ClassId == 4, Is.True, $"&{t.FileId}: its father is a Transform");
                    Assert.That(f!.RefList("m_Children"), Does.Contain(t.FileId));
                }

                foreach (long child in t.RefList("m_Children"))
                {
                    Assert.That(byId.TryGetValue(child, out Doc? c) && c.ClassId == 4, Is.True, $"&{t.FileId}: child {child} is a Transform");
                    Assert.That(c!.Ref("m_Father"), Is.EqualTo(t.FileId));
                }

                string rotation = t.Scalar("m_LocalRotation");
                double[] q = Regex.Matches(rotation, @"-?\d+(\.\d+)?(e-?\d+)?").Select(m => double.Parse(m.Value, System.Globalization.CultureInfo.InvariantCulture)).ToArray();
                Assert.That(q, Has.Length.EqualTo(4), rotation);
                Assert.That(q.Sum(x => x * x), Is.EqualTo(1.0).Within(1e-6), $"&{t.FileId}: a unit quaternion");
            }

            List<int> rootOrders = transforms.Where(t => t.Ref("m_Father") == 0).Select(t => int.Parse(t.Scalar("m_RootOrder"))).ToList();
            Assert.That(rootOrders.OrderBy(o => o), Is.EqualTo(Enumerable.Range(0, rootOrders.Count)), "root order 0..n-1");
        }

        [Test]
        public void EveryMonoBehaviour_SetsOnlyFieldsItsScriptSerializes_AndTheSceneIsWired()
        {
            List<Doc> docs = Docs();
            Dictionary<long, Doc> byId = docs.ToDictionary(d => d.FileId);
            Dictionary<string, string> metas = MetasByGuid();
            Type[] known = typeof(MagnusBallFlight).Assembly.GetTypes().Concat(typeof(TennisBall).Assembly.GetTypes()).ToArray();
            var scriptOf = new Dictionary<long, Type>();
            foreach (Doc mb in docs.Where(d => d.ClassId == 114))
            {
                string guid = Regex.Match(mb.Body, @"m_Script: \{fileID: 11500000, guid: ([0-9a-f]{32})").Groups[1].Value;
                string name = Path.GetFileNameWithoutExtension(metas[guid].Replace(".cs.meta", ".cs"));
                Type type = known.Single(t => t.Name == name && typeof(MonoBehaviour).IsAssignableFrom(t));
                scriptOf[mb.FileId] = type;
                string fields = mb.Body.Substring(mb.Body.IndexOf("  m_EditorClassIdentifier:", StringComparison.Ordinal));
                foreach (Match key in Regex.Matches(fields, @"^  (\w+):", RegexOptions.Multiline).Skip(1))
                {
                    FieldInfo? field = type.GetField(key.Groups[1].Value, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
                    Assert.That(field != null && (field.IsPublic || field.GetCustomAttribute<SerializeField>() != null), Is.True,
                        $"{type.Name} serializes a field {key.Groups[1].Value}");
                }
            }

            Doc Owner(Type script) => byId[byId[scriptOf.Single(s => s.Value == script).Key].Ref("m_GameObject")];
            long flight = scriptOf.Single(s => s.Value == typeof(MagnusBallFlight)).Key;
            Doc ball = Owner(typeof(MagnusBallFlight));
            Assert.That(Owner(typeof(TennisBall)).FileId, Is.EqualTo(ball.FileId), "TennisBall beside the flight it drives");
            Assert.That(ball.RefList("m_Component").Select(c => byId[c].ClassId), Is.SupersetOf(new[] { 4, 33, 23, 135 }), "a sphere: mesh, renderer, collider");
            Doc preview = byId[scriptOf.Single(s => s.Value == typeof(MagnusBallTrajectoryPreview)).Key];
            Assert.That(preview.Ref("flight"), Is.EqualTo(flight), "the preview follows the ball");
            Assert.That(byId[preview.Ref("m_GameObject")].RefList("m_Component").Select(c => byId[c].ClassId), Does.Contain(120), "beside its LineRenderer");
            Doc cameraSwitch = byId[scriptOf.Single(s => s.Value == typeof(CameraSwitch)).Key];
            Assert.That(byId[cameraSwitch.Ref("primaryCamera")].ClassId, Is.EqualTo(20));
            Assert.That(byId[cameraSwitch.Ref("secondaryCamera")].ClassId, Is.EqualTo(20));
            Assert.That(cameraSwitch.Ref("primaryCamera"), Is.Not.EqualTo(cameraSwitch.Ref("secondaryCamera")));
            Assert.That(scriptOf.Values, Does.Contain(typeof(CourtBuilder)));
            Assert.That(docs.Count(d => d.ClassId == 108), Is.EqualTo(1), "a light");
            Assert.That(docs.Single(d => d.ClassId == 104).Ref("m_Sun"), Is.EqualTo(docs.Single(d => d.ClassId == 108).FileId));
        }

        [Test]
        public void EveryFileAndFolderOfTheSample_HasAMeta_AndEveryMetaItsAsset()
        {
            var entries = Directory.EnumerateFileSystemEntries(Sample, "*", SearchOption.AllDirectories).ToList();
            List<string> missing = entries.Where(p => !p.EndsWith(".meta", StringComparison.Ordinal) && !File.Exists(p + ".meta"))
                .Select(p => Path.GetRelativePath(Sample, p)).ToList();
            Assert.That(missing, Is.Empty, "run bash tools/write-unity-meta.sh");
            List<string> orphans = entries.Where(p => p.EndsWith(".meta", StringComparison.Ordinal) && !File.Exists(p[..^5]) && !Directory.Exists(p[..^5]))
                .Select(p => Path.GetRelativePath(Sample, p)).ToList();
            Assert.That(orphans, Is.Empty);
            foreach (string kind in new[] { ".cs", ".unity", ".md" })
            {
                Assert.That(entries.Any(p => p.EndsWith(kind, StringComparison.Ordinal)), Is.True, "the sample has a " + kind);
            }

            Assert.That(MetasByGuid().Count, Is.GreaterThan(entries.Count(p => p.EndsWith(".meta", StringComparison.Ordinal))), "no two metas share a guid (MetasByGuid asserts it)");

            using JsonDocument manifest = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "package.json")));
            Assert.That(manifest.RootElement.GetProperty("samples").EnumerateArray().Select(s => s.GetProperty("path").GetString()), Does.Contain("Samples~/TennisScene"));
        }

        [Test]
        public void TheSampleReadme_NamesTheControls()
        {
            string readme = File.ReadAllText(Path.Combine(Sample, "README.md"));
            foreach (string key in new[] { "Space", "R", "F1", "F2", "TennisScene.unity", "TennisSceneBootstrap" })
            {
                Assert.That(readme, Does.Contain(key));
            }
        }

        [Test]
        public void TheBootstrap_BuildsTheScenesObjects_AndTheyPlay()
        {
            StubControl.DeltaTime = 1f / 60f;
            var holder = new GameObject("bootstrap");
            TennisSceneBootstrap bootstrap = Add<TennisSceneBootstrap>(holder);

            // Unity calls Awake as each component is added, then Start before the first Update: in that order here.
            GameObject ball = bootstrap.Ball.gameObject;
            GameObject path = bootstrap.Preview.gameObject;
            foreach (Component c in new Component[] { ball.GetComponent<RuntimeMaterial>(), bootstrap.Ball.Flight, path.GetComponent<RuntimeMaterial>(), bootstrap.Preview })
            {
                Call(c, "Awake");
            }

            foreach (Component c in new Component[] { bootstrap.Court.GetComponent<CourtBuilder>(), bootstrap.Ball, bootstrap.Cameras })
            {
                Call(c, "Start");
            }

            // The same objects, by name, as the scene file.
            var sceneNames = Docs().Where(d => d.ClassId == 1).Select(d => d.Scalar("m_Name")).ToList();
            var built = new[] { bootstrap.Court.name, ball.name, path.name, bootstrap.Cameras.primaryCamera.gameObject.name, bootstrap.Cameras.secondaryCamera.gameObject.name, bootstrap.Cameras.gameObject.name };
            Assert.That(sceneNames, Is.SupersetOf(built));
            Assert.That(bootstrap.Court.transform.Find(CourtBuilder.RootName), Is.Not.Null, "the court is built");
            Assert.That(bootstrap.Cameras.primaryCamera.enabled && !bootstrap.Cameras.secondaryCamera.enabled, Is.True);
            Assert.That(ball.GetComponent<Renderer>().sharedMaterial.color.r, Is.EqualTo(0.85f), "the ball's material is made at Awake");
            Assert.That(bootstrap.Ball.IsFlying, Is.True, "served at Start");
            Assert.That(ball.transform.localScale.x, Is.EqualTo(2 * (float)bootstrap.Ball.Flight.Model.Ball.Radius).Within(1e-6f), "the sphere is the ball's size");

            Call(bootstrap.Ball.Flight, "Update");
            Call(bootstrap.Preview, "LateUpdate");
            Assert.That(bootstrap.Preview.PointCount, Is.GreaterThan(50), "the predicted path is drawn");
        }
    }
}
