// A STUB of the few UnityEngine types the TennisScene sample scripts use, with Unity's own names and
// signatures, so that CI can compile src/MagnusBall/Samples~/TennisScene/Scripts without Unity (no Unity reference-assembly
// package restores from NuGet here). It is not Unity: the members keep values and do nothing else. Add a
// member here only when a script needs it, with the exact signature Unity's scripting reference gives.
using System;

namespace UnityEngine
{
    public class Object
    {
        public string name { get; set; } = string.Empty;
    }

    public class Component : Object
    {
        private Transform _transform;

        public Transform transform => gameObject != null ? gameObject.transform : _transform ?? (_transform = new Transform());

        public GameObject gameObject { get; internal set; }

        public T GetComponent<T>() => gameObject != null ? gameObject.GetComponent<T>() : default;
    }

    public class Behaviour : Component
    {
        public bool enabled { get; set; } = true;
    }

    public class MonoBehaviour : Behaviour
    {
    }

    public enum PrimitiveType
    {
        Sphere = 0,
        Capsule = 1,
        Cylinder = 2,
        Cube = 3,
        Plane = 4,
        Quad = 5,
    }

    public sealed class GameObject : Object
    {
        private readonly System.Collections.Generic.List<Component> _components = new System.Collections.Generic.List<Component>();

        public GameObject()
        {
            transform = new Transform { gameObject = this };
        }

        public Transform transform { get; }

        public static GameObject CreatePrimitive(PrimitiveType type)
        {
            var created = new GameObject { name = type.ToString() };
            created.AddComponent<MeshRenderer>();
            return created;
        }

        public T AddComponent<T>()
            where T : Component
        {
            T component = Activator.CreateInstance<T>();
            component.gameObject = this;
            _components.Add(component);
            return component;
        }

        public T GetComponent<T>()
        {
            foreach (Component component in _components)
            {
                if (component is T found)
                {
                    return found;
                }
            }

            return default;
        }
    }

    public class Transform : Component
    {
        public Vector3 position { get; set; }

        public Vector3 localPosition { get; set; }

        public Vector3 localScale { get; set; } = new Vector3(1, 1, 1);

        public Quaternion rotation { get; set; } = Quaternion.identity;

        private readonly System.Collections.Generic.List<Transform> _children = new System.Collections.Generic.List<Transform>();

        public Transform parent { get; private set; }

        public int childCount => _children.Count;

        public Transform GetChild(int index) => _children[index];

        public void SetParent(Transform parent, bool worldPositionStays)
        {
            this.parent?._children.Remove(this);
            this.parent = parent;
            parent?._children.Add(this);
        }
    }

    public class Material : Object
    {
        public Color color { get; set; }
    }

    public class Renderer : Component
    {
        public Material material { get; set; } = new Material();
    }

    public class MeshRenderer : Renderer
    {
    }

    public sealed class LineRenderer : Renderer
    {
        private Vector3[] _positions = new Vector3[0];

        public int positionCount
        {
            get => _positions.Length;
            set => Array.Resize(ref _positions, value);
        }

        public bool useWorldSpace { get; set; } = true;

        public void SetPosition(int index, Vector3 position) => _positions[index] = position;

        public Vector3 GetPosition(int index) => _positions[index];
    }

    public sealed class Camera : Behaviour
    {
    }

    public struct Vector3
    {
        public float x;
        public float y;
        public float z;

        public Vector3(float x, float y, float z)
        {
            this.x = x;
            this.y = y;
            this.z = z;
        }

        public static Vector3 zero => new Vector3(0, 0, 0);

        public override string ToString() => $"({x:F2}, {y:F2}, {z:F2})";
    }

    public struct Quaternion
    {
        public float x;
        public float y;
        public float z;
        public float w;

        public Quaternion(float x, float y, float z, float w)
        {
            this.x = x;
            this.y = y;
            this.z = z;
            this.w = w;
        }

        public static Quaternion identity => new Quaternion(0, 0, 0, 1);

        public static Quaternion AngleAxis(float angle, Vector3 axis)
        {
            double half = angle * Math.PI / 360.0;
            double length = Math.Sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
            double s = length > 0 ? Math.Sin(half) / length : 0;
            return new Quaternion((float)(axis.x * s), (float)(axis.y * s), (float)(axis.z * s), (float)Math.Cos(half));
        }

        public static Quaternion operator *(Quaternion a, Quaternion b) => new Quaternion(
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
            a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
    }

    public struct Color
    {
        public float r;
        public float g;
        public float b;
        public float a;

        public Color(float r, float g, float b, float a)
        {
            this.r = r;
            this.g = g;
            this.b = b;
            this.a = a;
        }

        public static Color white => new Color(1, 1, 1, 1);
    }

    public enum KeyCode
    {
        None = 0,
        Space = 32,
        R = 114,
        F1 = 282,
        F2 = 283,
    }

    public static class Input
    {
        /// <summary>Stub: keys "pressed this frame"; tests may fill it.</summary>
        public static readonly System.Collections.Generic.HashSet<KeyCode> StubKeysDown = new System.Collections.Generic.HashSet<KeyCode>();

        public static bool GetKeyDown(KeyCode key) => StubKeysDown.Contains(key);
    }

    public static class Time
    {
        public static float deltaTime { get; set; } = 1f / 60f;

        public static float fixedDeltaTime { get; set; } = 0.02f;
    }

    public static class Debug
    {
        public static void Log(object message) => Console.WriteLine(message);
    }

    [AttributeUsage(AttributeTargets.Field, AllowMultiple = true)]
    public class HeaderAttribute : Attribute
    {
        public HeaderAttribute(string header) => this.header = header;

        public readonly string header;
    }

    [AttributeUsage(AttributeTargets.Field, AllowMultiple = true)]
    public class TooltipAttribute : Attribute
    {
        public TooltipAttribute(string tooltip) => this.tooltip = tooltip;

        public readonly string tooltip;
    }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponent : Attribute
    {
        public RequireComponent(Type requiredComponent) => m_Type0 = requiredComponent;

        public Type m_Type0;
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class ContextMenu : Attribute
    {
        public ContextMenu(string itemName) => menuItem = itemName;

        public readonly string menuItem;
    }
}
