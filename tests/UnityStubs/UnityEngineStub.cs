// A STUB of the few UnityEngine types that MagnusBall.Unity (src/MagnusBall/Runtime/Unity) and the TennisScene
// sample scripts use, with Unity's own names and signatures (Unity 6000.0; every public member is listed in
// unity-api-reference.txt with the file of UnityCsReference it was checked in, and StubApiTests fails on a
// public member that is not listed). It is not Unity: the members keep values and do nothing else, except
// where Unity's behaviour is what a script could get wrong (Object's destroyed-object null, Renderer.material
// instantiating a copy, LineRenderer.SetPositions ignoring points beyond positionCount). Tests drive it
// (frame time, keys, collisions) through MagnusBall.UnityStubs.StubControl, which scripts cannot see.
using System;
using System.Collections.Generic;
using MagnusBall.UnityStubs;

namespace UnityEngine
{
    public class Object
    {
        internal bool StubDestroyed;

        private string _name = string.Empty;

        // Unity: a component's name is its GameObject's (reading and writing it).
        public string name
        {
            get => this is Component c && c.gameObject != null ? c.gameObject.name : _name;
            set
            {
                if (this is Component c && c.gameObject != null)
                {
                    c.gameObject.name = value;
                }
                else
                {
                    _name = value;
                }
            }
        }

        // Unity: a destroyed object compares equal to null and converts to false.
        public static bool operator ==(Object x, Object y) => Compare(x, y);

        public static bool operator !=(Object x, Object y) => !Compare(x, y);

        public static implicit operator bool(Object exists) => !Compare(exists, null);

        public override bool Equals(object other) => other is Object o ? Compare(this, o) : other == null && StubDestroyed;

        public override int GetHashCode() => base.GetHashCode();

        public static void Destroy(Object obj) => StubControl.Destroy(obj);

        public static void DestroyImmediate(Object obj) => StubControl.Destroy(obj);

        private static bool Compare(Object x, Object y)
        {
            bool xNull = ReferenceEquals(x, null) || x.StubDestroyed;
            bool yNull = ReferenceEquals(y, null) || y.StubDestroyed;
            if (xNull && yNull)
            {
                return true;
            }

            return !xNull && !yNull && ReferenceEquals(x, y);
        }
    }

    public class Component : Object
    {
        private Transform _transform;

        public Transform transform => gameObject != null ? gameObject.transform : _transform ?? (_transform = new Transform(null));

        public GameObject gameObject => StubGameObject;

        internal GameObject StubGameObject;

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
        internal readonly List<Component> StubComponents = new List<Component>();

        public GameObject()
        {
            transform = new Transform(this);
        }

        public GameObject(string name)
            : this()
        {
            this.name = name;
        }

        public Transform transform { get; }

        public static GameObject CreatePrimitive(PrimitiveType type)
        {
            var created = new GameObject(type.ToString());
            created.AddComponent<MeshRenderer>().sharedMaterial = StubControl.DefaultMaterial;
            return created;
        }

        public T AddComponent<T>()
            where T : Component
        {
            T component = Activator.CreateInstance<T>();
            component.StubGameObject = this;
            StubComponents.Add(component);
            return component;
        }

        public T GetComponent<T>()
        {
            foreach (Component component in StubComponents)
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
        internal readonly List<Transform> StubChildren = new List<Transform>();
        private Transform _parent;

        // Unity: protected; transforms come with their GameObject.
        protected Transform()
        {
        }

        internal Transform(GameObject owner) => StubGameObject = owner;

        // Unity keeps the local position, rotation and scale; the world position and rotation are the parents'
        // transforms applied in turn (the same as Unity's localToWorldMatrix for a point), so for a transform
        // without a parent position is localPosition and rotation is the local rotation.
        private Vector3 _localPosition;
        private Quaternion _localRotation = Quaternion.identity;

        public Vector3 position
        {
            get => _parent == null ? _localPosition : _parent.StubToWorld(_localPosition);
            set => _localPosition = _parent == null ? value : _parent.StubToLocal(value);
        }

        public Vector3 localPosition
        {
            get => _localPosition;
            set => _localPosition = value;
        }

        public Vector3 localScale { get; set; } = new Vector3(1, 1, 1);

        public Quaternion rotation
        {
            get => _parent == null ? _localRotation : _parent.rotation * _localRotation;
            set => _localRotation = _parent == null ? value : _parent.rotation.StubInverse() * value;
        }

        public Transform parent
        {
            get => _parent;
            set => SetParent(value);
        }

        // A point in this transform's local space, in world space: scale, rotate, translate, then the parent's.
        internal Vector3 StubToWorld(Vector3 local)
        {
            Vector3 s = localScale;
            Vector3 inParent = _localRotation.StubRotate(new Vector3(local.x * s.x, local.y * s.y, local.z * s.z)).StubPlus(_localPosition);
            return _parent == null ? inParent : _parent.StubToWorld(inParent);
        }

        internal Vector3 StubToLocal(Vector3 world)
        {
            Vector3 inParent = _parent == null ? world : _parent.StubToLocal(world);
            Vector3 r = _localRotation.StubInverse().StubRotate(inParent.StubPlus(_localPosition.StubTimes(-1)));
            Vector3 s = localScale;
            return new Vector3(r.x / s.x, r.y / s.y, r.z / s.z);
        }

        // Unity: the point through the transform's localToWorldMatrix (scale, rotate, translate, then the parents').
        public Vector3 TransformPoint(Vector3 position) => StubToWorld(position);

        public int childCount => StubChildren.Count;

        public Transform GetChild(int index) => StubChildren[index];

        public Transform Find(string n)
        {
            foreach (Transform child in StubChildren)
            {
                if (child.gameObject != null && child.gameObject.name == n)
                {
                    return child;
                }
            }

            return null;
        }

        public void SetParent(Transform p) => SetParent(p, true);

        // worldPositionStays: the world position and rotation are kept (the local ones change); Unity also adjusts
        // localScale to keep the world scale, which the stub does not (no script here reparents a scaled object so).
        public void SetParent(Transform parent, bool worldPositionStays)
        {
            Vector3 world = position;
            Quaternion worldRotation = rotation;
            _parent?.StubChildren.Remove(this);
            _parent = parent;
            parent?.StubChildren.Add(this);
            if (worldPositionStays)
            {
                position = world;
                rotation = worldRotation;
            }
        }
    }

    public sealed class Shader : Object
    {
        private Shader()
        {
        }
    }

    public class Material : Object
    {
        public Material(Shader shader)
        {
            StubControl.MaterialsCreated++;
        }

        public Material(Material source)
        {
            color = source.color;
            StubControl.MaterialsCreated++;
        }

        [Obsolete("Creating materials from shader source string is no longer supported. Use Shader assets instead.", false)]
        public Material(string contents)
        {
            StubControl.MaterialsCreated++;
        }

        public Color color { get; set; }
    }

    public class Renderer : Component
    {
        private Material _material;
        private bool _instantiated;

        // Unity: the first read of .material instantiates a copy of the shared material for this renderer.
        public Material material
        {
            get
            {
                if (!_instantiated && _material != null)
                {
                    _material = new Material(_material);
                }

                _instantiated = true;
                return _material;
            }
            // Unity: the same native SetMaterial as sharedMaterial's setter (Renderer.material { set }), so
            // what a later read of .material does cannot depend on which setter assigned it.
            set => sharedMaterial = value;
        }

        public Material sharedMaterial
        {
            get => _material;
            set
            {
                _material = value;
                _instantiated = false;
            }
        }
    }

    public class MeshRenderer : Renderer
    {
    }

    public sealed class LineRenderer : Renderer
    {
        // Unity keeps the points natively; the stub keeps a buffer that only grows, so setting
        // positionCount allocates no managed memory once the buffer is large enough (as in Unity: none).
        // Unity: a new LineRenderer has two points, (0, 0, 0) and (0, 0, 1), until a script sets positionCount.
        private Vector3[] _positions = { new Vector3(0, 0, 0), new Vector3(0, 0, 1) };
        private int _count = 2;

        public int positionCount
        {
            get => _count;
            set
            {
                if (value > _positions.Length)
                {
                    Array.Resize(ref _positions, value);
                }

                for (int i = _count; i < value; i++)
                {
                    _positions[i] = Vector3.zero;
                }

                _count = value;
            }
        }

        public bool useWorldSpace { get; set; } = true;

        public float widthMultiplier { get; set; } = 1;

        public void SetPosition(int index, Vector3 position) => _positions[Check(index)] = position;

        public Vector3 GetPosition(int index) => _positions[Check(index)];

        // Unity: positionCount must be set first; points beyond it are ignored.
        public void SetPositions(Vector3[] positions) => Array.Copy(positions, _positions, Math.Min(positions.Length, _count));

        public int GetPositions(Vector3[] positions)
        {
            int count = Math.Min(positions.Length, _count);
            Array.Copy(_positions, positions, count);
            return count;
        }

        private int Check(int index) => index >= 0 && index < _count ? index : throw new IndexOutOfRangeException();
    }

    public sealed class Camera : Behaviour
    {
        public float depth { get; set; }
    }

    public enum ForceMode
    {
        Force = 0,
        Acceleration = 5,
        Impulse = 1,
        VelocityChange = 2,
    }

    // Unity's colliders, as far as MagnusBall.Components.ColliderShapes reads them: the geometry in the object's local space.
    public partial class Collider : Component
    {
    }

    public partial class BoxCollider : Collider
    {
        public Vector3 center { get; set; }

        public Vector3 size { get; set; } = new Vector3(1, 1, 1);
    }

    public class CapsuleCollider : Collider
    {
        public Vector3 center { get; set; }

        public float radius { get; set; } = 0.5f;

        public float height { get; set; } = 2;

        public int direction { get; set; } = 1;
    }

    public class SphereCollider : Collider
    {
        public Vector3 center { get; set; }

        public float radius { get; set; } = 0.5f;
    }

    public class Rigidbody : Component
    {
        // What AddForce accumulated this step, as an acceleration (StubControl.SimulateStep integrates it).
        internal Vector3 StubAcceleration;
        internal Vector3 StubVelocityChange;

        public Vector3 linearVelocity { get; set; }

        // Unity 6's obsolete alias (Rigidbody.deprecated.cs), the real name before 6000.0: MagnusBall.Unity.Compile.Pre6 compiles the
        // components' pre-Unity-6 branch against it.
        [System.Obsolete("Please use Rigidbody.linearVelocity instead. (UnityUpgradable) -> linearVelocity")]
        public Vector3 velocity { get => linearVelocity; set => linearVelocity = value; }

        public Vector3 angularVelocity { get; set; }

        public float mass { get; set; } = 1;

        public bool useGravity { get; set; } = true;

        public bool isKinematic { get; set; }

        public Vector3 position { get; set; }

        // Unity 6: a new body takes Physics.defaultMaxAngularSpeed, 50 rad/s in a new project (7 before Unity 2022).
        public float maxAngularVelocity { get; set; } = 50;

        public void AddForce(Vector3 force) => AddForce(force, ForceMode.Force);

        public void AddForce(Vector3 force, ForceMode mode)
        {
            switch (mode)
            {
                case ForceMode.Force:
                    StubAcceleration = StubAcceleration.StubPlus(force.StubTimes(1f / mass));
                    break;
                case ForceMode.Acceleration:
                    StubAcceleration = StubAcceleration.StubPlus(force);
                    break;
                case ForceMode.Impulse:
                    StubVelocityChange = StubVelocityChange.StubPlus(force.StubTimes(1f / mass));
                    break;
                default:
                    StubVelocityChange = StubVelocityChange.StubPlus(force);
                    break;
            }
        }
    }

    public struct ContactPoint
    {
        internal ContactPoint(Vector3 point, Vector3 normal)
        {
            StubPoint = point;
            StubNormal = normal;
        }

        private readonly Vector3 StubPoint;
        private readonly Vector3 StubNormal;

        public Vector3 point => StubPoint;

        public Vector3 normal => StubNormal;
    }

    public class Collision
    {
        internal ContactPoint[] StubContacts = new ContactPoint[0];
        internal Rigidbody StubRigidbody;

        public Rigidbody rigidbody => StubRigidbody;

        public int contactCount => StubContacts.Length;

        // Unity: an index outside [0, contactCount) is an ArgumentOutOfRangeException (Collision.cs), not an array's.
        public ContactPoint GetContact(int index) =>
            index >= 0 && index < StubContacts.Length
                ? StubContacts[index]
                : throw new ArgumentOutOfRangeException($"Cannot get contact at index {index}. There are {StubContacts.Length} contact(s).");
    }

    public class Physics
    {
        public static Vector3 gravity { get; set; } = new Vector3(0, -9.81f, 0);
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
        public static Vector3 up => new Vector3(0, 1, 0);

        internal Vector3 StubPlus(Vector3 b) => new Vector3(x + b.x, y + b.y, z + b.z);

        internal Vector3 StubTimes(float s) => new Vector3(x * s, y * s, z * s);

        // Unity: "F2" in the invariant culture, whatever the machine's culture.
        public override string ToString() => FormattableString.Invariant($"({x:F2}, {y:F2}, {z:F2})");
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

        // The conjugate: the inverse of a unit rotation.
        internal Quaternion StubInverse() => new Quaternion(-x, -y, -z, w);

        // v rotated by this unit quaternion: v + 2w (q x v) + 2 q x (q x v), q = (x, y, z).
        internal Vector3 StubRotate(Vector3 v)
        {
            float tx = 2 * (y * v.z - z * v.y), ty = 2 * (z * v.x - x * v.z), tz = 2 * (x * v.y - y * v.x);
            return new Vector3(
                v.x + w * tx + (y * tz - z * ty),
                v.y + w * ty + (z * tx - x * tz),
                v.z + w * tz + (x * ty - y * tx));
        }

        public static Quaternion AngleAxis(float angle, Vector3 axis)
        {
            double half = angle * Math.PI / 360.0;
            double length = Math.Sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
            double s = length > 0 ? Math.Sin(half) / length : 0;
            return new Quaternion((float)(axis.x * s), (float)(axis.y * s), (float)(axis.z * s), (float)Math.Cos(half));
        }

        public static Quaternion operator *(Quaternion lhs, Quaternion rhs) => new Quaternion(
            lhs.w * rhs.x + lhs.x * rhs.w + lhs.y * rhs.z - lhs.z * rhs.y,
            lhs.w * rhs.y + lhs.y * rhs.w + lhs.z * rhs.x - lhs.x * rhs.z,
            lhs.w * rhs.z + lhs.z * rhs.w + lhs.x * rhs.y - lhs.y * rhs.x,
            lhs.w * rhs.w - lhs.x * rhs.x - lhs.y * rhs.y - lhs.z * rhs.z);
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

        public static Color yellow => new Color(1F, 235F / 255F, 4F / 255F, 1F);

        public static Color cyan => new Color(0F, 1F, 1F, 1F);

        public static Color green => new Color(0F, 1F, 0F, 1F);
    }

    public enum KeyCode
    {
        None = 0,
        Space = 32,
        Alpha0 = 48,
        Alpha9 = 57,
        A = 97,
        R = 114,
        Z = 122,
        F1 = 282,
        F2 = 283,
        F12 = 293,
    }

    public class Input
    {
        public static bool GetKeyDown(KeyCode key) => StubControl.LegacyKeysDown.Contains(key);
    }

    public class Time
    {
        // Unity: inside FixedUpdate, deltaTime is fixedDeltaTime.
        public static float deltaTime => StubControl.InFixedUpdate ? fixedDeltaTime : StubControl.DeltaTime;

        public static float fixedDeltaTime { get; set; } = 0.02f;
    }

    public class Debug
    {
        public static void Log(object message) => Console.WriteLine(message);

        // The stub keeps warnings and errors for tests (StubControl.Logged) and prints them, as Unity's console shows them.
        public static void LogWarning(object message, Object context) => StubControl.Log("Warning", message);

        public static void LogError(object message, Object context) => StubControl.Log("Error", message);
    }

    // Unity draws these in the Scene view; the stub records each line (StubControl.GizmoLines) in the current colour.
    public sealed class Gizmos
    {
        public static Color color { get; set; } = Color.white;

        public static void DrawLine(Vector3 from, Vector3 to) => StubControl.GizmoLines.Add((from, to, color));
    }

    public partial struct Plane
    {
        private Vector3 m_Normal;
        private float m_Distance;

        // Unity: the normal is normalized; distance = -Dot(normal, inPoint).
        public Plane(Vector3 inNormal, Vector3 inPoint)
        {
            double length = Math.Sqrt(inNormal.x * inNormal.x + inNormal.y * inNormal.y + inNormal.z * inNormal.z);
            m_Normal = length > 1e-5 ? inNormal.StubTimes((float)(1 / length)) : Vector3.zero;
            m_Distance = -(m_Normal.x * inPoint.x + m_Normal.y * inPoint.y + m_Normal.z * inPoint.z);
        }

        public Vector3 normal
        {
            get => m_Normal;
            set => m_Normal = value;
        }

        public float distance
        {
            get => m_Distance;
            set => m_Distance = value;
        }

        public float GetDistanceToPoint(Vector3 point) => m_Normal.x * point.x + m_Normal.y * point.y + m_Normal.z * point.z + m_Distance;
    }

    [AttributeUsage(AttributeTargets.Field | AttributeTargets.Property, Inherited = true, AllowMultiple = false)]
    public sealed class MinAttribute : PropertyAttribute
    {
        public readonly float min;

        public MinAttribute(float min) => this.min = min;
    }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = false)]
    public class HelpURLAttribute : Attribute
    {
        private readonly string m_Url;

        public HelpURLAttribute(string url) => m_Url = url;

        public virtual string URL => m_Url;
    }

    public sealed class HideInInspector : Attribute
    {
    }

    public sealed class SerializeField : Attribute
    {
    }

    public interface ISerializationCallbackReceiver
    {
        void OnBeforeSerialize();

        void OnAfterDeserialize();
    }

    [AttributeUsage(AttributeTargets.Field | AttributeTargets.Property, Inherited = true, AllowMultiple = false)]
    public abstract class PropertyAttribute : Attribute
    {
        protected PropertyAttribute()
        {
        }

        public int order { get; set; }
    }

    [AttributeUsage(AttributeTargets.Field | AttributeTargets.Property, Inherited = true, AllowMultiple = true)]
    public class HeaderAttribute : PropertyAttribute
    {
        public readonly string header;

        public HeaderAttribute(string header) => this.header = header;
    }

    [AttributeUsage(AttributeTargets.All, Inherited = true, AllowMultiple = false)]
    public class TooltipAttribute : PropertyAttribute
    {
        public readonly string tooltip;

        public TooltipAttribute(string tooltip) => this.tooltip = tooltip;
    }

    [AttributeUsage(AttributeTargets.Field | AttributeTargets.Property, Inherited = true, AllowMultiple = false)]
    public sealed class RangeAttribute : PropertyAttribute
    {
        public readonly float min;
        public readonly float max;

        public RangeAttribute(float min, float max)
        {
            this.min = min;
            this.max = max;
        }
    }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponent : Attribute
    {
        public Type m_Type0;

        public RequireComponent(Type requiredComponent) => m_Type0 = requiredComponent;
    }

    public sealed class AddComponentMenu : Attribute
    {
        public AddComponentMenu(string menuName) => componentMenu = menuName;

        public string componentMenu { get; }
    }

    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public sealed class DisallowMultipleComponent : Attribute
    {
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class ContextMenu : Attribute
    {
        public readonly string menuItem;

        public ContextMenu(string itemName) => menuItem = itemName;
    }
}
