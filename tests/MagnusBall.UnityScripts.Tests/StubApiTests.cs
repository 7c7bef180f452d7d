using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Reflection;
using NUnit.Framework;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// The UnityEngine stub may only be a subset of Unity's API: every public type and member it declares in
    /// the UnityEngine namespaces must be listed in tests/UnityStubs/unity-api-reference.txt, the signatures
    /// checked by hand against Unity's C# reference source (and the Input System package's source), with the
    /// branch, commit and file noted there. A member added to the stub without checking fails here.
    /// </summary>
    [TestFixture]
    public class StubApiTests
    {
        private static readonly Assembly Stub = typeof(UnityEngine.Object).Assembly;

        /// <summary>The stub's public API, one normalized signature a line (the reference file's format).</summary>
        internal static IEnumerable<string> Signatures()
        {
            foreach (Type type in Stub.GetExportedTypes().Where(t => t.Namespace != null && t.Namespace.StartsWith("UnityEngine", StringComparison.Ordinal)).OrderBy(t => t.FullName, StringComparer.Ordinal))
            {
                yield return TypeLine(type);
                const BindingFlags declared = BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
                foreach (MemberInfo member in type.GetMembers(declared).OrderBy(m => m.Name, StringComparer.Ordinal).ThenBy(m => m.ToString(), StringComparer.Ordinal))
                {
                    string? line = MemberLine(type, member);
                    if (line != null)
                    {
                        yield return line;
                    }
                }
            }
        }

        private static string TypeLine(Type t)
        {
            string kind = t.IsEnum ? "enum" : t.IsValueType ? "struct" : t.IsInterface ? "interface"
                : t.IsAbstract && t.IsSealed ? "static class" : t.IsAbstract ? "abstract class" : t.IsSealed ? "sealed class" : "class";
            string line = $"{kind} {t.FullName}";
            if (t.BaseType != null && t.BaseType != typeof(object) && t.BaseType != typeof(ValueType) && t.BaseType != typeof(Enum))
            {
                line += " : " + Name(t.BaseType);
            }

            AttributeUsageAttribute? usage = t.GetCustomAttribute<AttributeUsageAttribute>(inherit: false);
            if (usage != null)
            {
                line += $" [AttributeUsage({usage.ValidOn}, AllowMultiple={usage.AllowMultiple}, Inherited={usage.Inherited})]";
            }

            return line;
        }

        private static string? MemberLine(Type t, MemberInfo member)
        {
            string owner = t.FullName!;
            switch (member)
            {
                case ConstructorInfo c:
                    return $"ctor {owner}({Parameters(c)})";
                case MethodInfo m when !m.IsSpecialName || m.Name.StartsWith("op_", StringComparison.Ordinal):
                    string generic = m.IsGenericMethodDefinition ? "<" + string.Join(", ", m.GetGenericArguments().Select(a => a.Name)) + ">" : string.Empty;
                    return $"method {(m.IsStatic ? "static " : string.Empty)}{Name(m.ReturnType)} {owner}.{m.Name}{generic}({Parameters(m)})";
                case PropertyInfo p:
                    MethodInfo? get = p.GetGetMethod(), set = p.GetSetMethod();
                    bool isStatic = (get ?? set)!.IsStatic;
                    ParameterInfo[] index = p.GetIndexParameters();
                    string name = index.Length > 0 ? "this[" + string.Join(", ", index.Select(i => Name(i.ParameterType))) + "]" : p.Name;
                    return $"property {(isStatic ? "static " : string.Empty)}{Name(p.PropertyType)} {owner}.{name} {{{(get != null ? " get;" : string.Empty)}{(set != null ? " set;" : string.Empty)} }}";
                case FieldInfo f when t.IsEnum:
                    return f.IsSpecialName ? null : $"enum {owner}.{f.Name} = {Convert.ToInt64(f.GetRawConstantValue())}";
                case FieldInfo f:
                    return $"field {(f.IsStatic ? "static " : string.Empty)}{(f.IsInitOnly ? "readonly " : string.Empty)}{Name(f.FieldType)} {owner}.{f.Name}";
                case EventInfo e:
                    return $"event {Name(e.EventHandlerType!)} {owner}.{e.Name}";
                case Type nested:
                    return $"nested {nested.FullName}";
                default:
                    return null; // accessors (listed with their property)
            }
        }

        private static string Parameters(MethodBase method) =>
            string.Join(", ", method.GetParameters().Select(p => Name(p.ParameterType) + " " + p.Name));

        private static string Name(Type type)
        {
            if (type.IsGenericParameter)
            {
                return type.Name;
            }

            if (type.IsArray)
            {
                return Name(type.GetElementType()!) + "[]";
            }

            return type.FullName ?? type.Name;
        }

        private static HashSet<string> Reference()
        {
            string path = Path.Combine(UnityLoop.RepositoryRoot(), "tests", "UnityStubs", "unity-api-reference.txt");
            return new HashSet<string>(
                File.ReadAllLines(path)
                    .Select(l => l.Split('#')[0].Trim())
                    .Where(l => l.Length > 0),
                StringComparer.Ordinal);
        }

        [Test]
        public void EveryPublicMemberOfTheStub_IsInUnitysReferenceList()
        {
            HashSet<string> reference = Reference();
            List<string> missing = Signatures().Where(s => !reference.Contains(s)).ToList();
            Assert.That(missing, Is.Empty,
                "public stub members not in tests/UnityStubs/unity-api-reference.txt (check them in UnityCsReference, then list them):\n" +
                string.Join("\n", missing));
        }

        [Test]
        public void TheReferenceList_HasNoEntryTheStubLacks()
        {
            // Stale lines would let a member come back unchecked after its signature changed.
            var stub = new HashSet<string>(Signatures(), StringComparer.Ordinal);
            List<string> stale = Reference().Where(r => !stub.Contains(r)).ToList();
            Assert.That(stale, Is.Empty, "lines of unity-api-reference.txt the stub no longer has:\n" + string.Join("\n", stale));
        }

        [Test]
        public void Vector3ToString_IsF2InTheInvariantCulture_WhateverTheMachinesCulture()
        {
            // UnityCsReference 6000.0, Runtime/Export/Math/Vector3.cs: ToString() is ToString("F2",
            // CultureInfo.InvariantCulture.NumberFormat). The stub used the current culture: "(1,50, ...)" in German.
            CultureInfo before = CultureInfo.CurrentCulture;
            try
            {
                CultureInfo.CurrentCulture = new CultureInfo("de-DE");
                Assert.That(new UnityEngine.Vector3(1.5f, -2f, 0.254f).ToString(), Is.EqualTo("(1.50, -2.00, 0.25)"));
            }
            finally
            {
                CultureInfo.CurrentCulture = before;
            }
        }

        [Test]
        public void RendererMaterialsSetter_IsSharedMaterialsSetter()
        {
            // Unity's Renderer.material and sharedMaterial setters both call the same native SetMaterial
            // (Runtime/Export/Graphics/GraphicsRenderers.bindings.cs), so a later read of .material cannot tell
            // which one assigned the material: both read a copy.
            var shared = new UnityEngine.Material((UnityEngine.Shader)null!);
            UnityEngine.MeshRenderer byMaterial = new UnityEngine.GameObject().AddComponent<UnityEngine.MeshRenderer>();
            UnityEngine.MeshRenderer byShared = new UnityEngine.GameObject().AddComponent<UnityEngine.MeshRenderer>();
            byMaterial.material = shared;
            byShared.sharedMaterial = shared;
            Assert.That(ReferenceEquals(byMaterial.material, shared), Is.EqualTo(ReferenceEquals(byShared.material, shared)));
            Assert.That(ReferenceEquals(byMaterial.material, shared), Is.False, "read through .material: the renderer's own copy");
        }

        [Test]
        public void TheKeyboardsIndexer_ThrowsForAKeyWithNoControl()
        {
            // The Input System's Keyboard[Key] (Devices/Keyboard.cs) throws ArgumentOutOfRangeException(nameof(key))
            // for Key.None; the stub returned a control.
            var keyboard = new UnityEngine.InputSystem.Keyboard();
            var thrown = Assert.Throws<ArgumentOutOfRangeException>(() => _ = keyboard[UnityEngine.InputSystem.Key.None]);
            Assert.That(thrown!.ParamName, Is.EqualTo("key"));
            Assert.That(keyboard[UnityEngine.InputSystem.Key.Space].keyCode, Is.EqualTo(UnityEngine.InputSystem.Key.Space));
        }

        private sealed class DeltaRecorder : UnityEngine.MonoBehaviour
        {
            public float InUpdate, InFixedUpdate;

            private void Update() => InUpdate = UnityEngine.Time.deltaTime;

            private void FixedUpdate() => InFixedUpdate = UnityEngine.Time.deltaTime;
        }

        [Test]
        [NonParallelizable] // Time is static, as in Unity
        public void TimeDeltaTime_InsideFixedUpdate_IsFixedDeltaTime()
        {
            // Unity's Time.deltaTime "when called from inside FixedUpdate returns Time.fixedDeltaTime"; the stub
            // returned the frame time there (no script here reads it in FixedUpdate yet; one that did would be wrong).
            float before = UnityEngine.Time.fixedDeltaTime, frame = MagnusBall.UnityStubs.StubControl.DeltaTime;
            try
            {
                UnityEngine.Time.fixedDeltaTime = 0.02f;
                MagnusBall.UnityStubs.StubControl.DeltaTime = 1f / 144f;
                DeltaRecorder script = new UnityEngine.GameObject().AddComponent<DeltaRecorder>();
                UnityLoop.Call(script, "Update");
                UnityLoop.Call(script, "FixedUpdate");
                Assert.That(script.InUpdate, Is.EqualTo(1f / 144f));
                Assert.That(script.InFixedUpdate, Is.EqualTo(0.02f));
                UnityLoop.Message(script, "FixedUpdate")();
                Assert.That(script.InFixedUpdate, Is.EqualTo(0.02f), "through the allocation-free delegate too");
                Assert.That(UnityEngine.Time.deltaTime, Is.EqualTo(1f / 144f), "and the frame time again outside it");
            }
            finally
            {
                UnityEngine.Time.fixedDeltaTime = before;
                MagnusBall.UnityStubs.StubControl.DeltaTime = frame;
            }
        }

        [Test]
        public void CollisionGetContact_OutOfRange_IsAnArgumentOutOfRangeException()
        {
            // Modules/Physics/Managed/Collision.cs checks the index itself; the stub let the array throw
            // IndexOutOfRangeException, which a script catching Unity's exception would not catch.
            UnityEngine.Collision collision = MagnusBall.UnityStubs.StubControl.Collision(new UnityEngine.Vector3(0, 0, 0), new UnityEngine.Vector3(0, 1, 0));
            Assert.That(collision.GetContact(0).normal.y, Is.EqualTo(1f));
            Assert.Throws<ArgumentOutOfRangeException>(() => collision.GetContact(1));
            Assert.Throws<ArgumentOutOfRangeException>(() => collision.GetContact(-1));
        }

        [Test]
        public void TransformPosition_IsTheWorldPosition_ThroughItsParents()
        {
            // Unity: position is the world position, localPosition the position in the parent's space (scaled,
            // rotated, translated by it); without a parent they are one. The stub kept them as two unrelated values.
            var parent = new UnityEngine.GameObject("parent").transform;
            parent.position = new UnityEngine.Vector3(1, 2, 3);
            parent.rotation = UnityEngine.Quaternion.AngleAxis(90, new UnityEngine.Vector3(0, 1, 0)); // +z turns to +x
            parent.localScale = new UnityEngine.Vector3(2, 2, 2);
            Assert.That(parent.localPosition, Is.EqualTo(parent.position), "a root's position is its localPosition");

            var child = new UnityEngine.GameObject("child").transform;
            child.SetParent(parent, false);
            child.localPosition = new UnityEngine.Vector3(0, 0, 1);
            // (1, 2, 3) + R (0, 0, 2) = (3, 2, 3); 1e-6: float rounding of sin/cos 45 degrees on numbers near 3.
            AssertNear(child.position, 3, 2, 3, "the child's world position");
            child.position = new UnityEngine.Vector3(1, 4, 3);
            AssertNear(child.localPosition, 0, 1, 0, "set in world space, kept in the parent's");

            var other = new UnityEngine.GameObject("other").transform;
            other.position = new UnityEngine.Vector3(5, 0, 0);
            other.SetParent(parent, true);
            AssertNear(other.position, 5, 0, 0, "worldPositionStays keeps the world position");
            // R^-1 ((5, 0, 0) - (1, 2, 3)) / 2 = R^-1 (4, -2, -3) / 2 = (3, -2, 4) / 2.
            AssertNear(other.localPosition, 1.5f, -1, 2, "and changes the local one");
        }

        private static void AssertNear(UnityEngine.Vector3 v, float x, float y, float z, string what)
        {
            Assert.That(v.x, Is.EqualTo(x).Within(1e-6), what + ": x");
            Assert.That(v.y, Is.EqualTo(y).Within(1e-6), what + ": y");
            Assert.That(v.z, Is.EqualTo(z).Within(1e-6), what + ": z");
        }

        [Test]
        public void TheStubsTestHook_IsNotVisibleToScripts()
        {
            Type hook = Stub.GetType("MagnusBall.UnityStubs.StubControl", throwOnError: true)!;
            Assert.That(hook.IsPublic, Is.False, "internal: only the tests (InternalsVisibleTo) reach it");
            Assert.That(typeof(UnityEngine.Time).GetProperty("deltaTime")!.CanWrite, Is.False, "Time.deltaTime is get-only, as in Unity");
            Assert.That(typeof(UnityEngine.Material).GetConstructor(Type.EmptyTypes), Is.Null, "Unity's Material has no parameterless constructor");
            Assert.That(typeof(UnityEngine.TooltipAttribute).BaseType, Is.EqualTo(typeof(UnityEngine.PropertyAttribute)));
        }
    }
}
