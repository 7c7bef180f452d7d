using System.Collections.Generic;
using UnityEngine;
using UnityEngine.InputSystem;

namespace MagnusBall.UnityStubs
{
    /// <summary>
    /// The test-only side of the UnityEngine stub: what Unity's engine would set (frame time, keys pressed this
    /// frame, collisions) and what the stub counts. Internal, outside the UnityEngine namespace: the scripts
    /// under test cannot reach it, only tests (InternalsVisibleTo) can.
    /// </summary>
    internal static class StubControl
    {
        /// <summary>What <c>Time.deltaTime</c> returns (Unity: get-only, set by the engine each frame).</summary>
        internal static float DeltaTime = 1f / 60f;

        /// <summary>
        /// True while a test calls a script's FixedUpdate (UnityLoop does): <c>Time.deltaTime</c> then returns
        /// <c>Time.fixedDeltaTime</c>, as Unity's does inside FixedUpdate.
        /// </summary>
        internal static bool InFixedUpdate;

        /// <summary>Keys <c>Input.GetKeyDown</c> reports as pressed this frame (the Input Manager).</summary>
        internal static readonly HashSet<KeyCode> LegacyKeysDown = new HashSet<KeyCode>();

        /// <summary>Keys <c>KeyControl.wasPressedThisFrame</c> reports as pressed this frame (the Input System).</summary>
        internal static readonly HashSet<Key> InputSystemKeysDown = new HashSet<Key>();

        /// <summary>How many materials were created (new Material, or Renderer.material's copy).</summary>
        internal static int MaterialsCreated;

        /// <summary>The shared default material CreatePrimitive's renderers get.</summary>
        internal static readonly Material DefaultMaterial = new Material((Shader)null);

        /// <summary>Every <c>Debug.LogWarning</c> and <c>Debug.LogError</c> so far, as "Warning: message" / "Error: message".</summary>
        internal static readonly List<string> Logged = new List<string>();

        /// <summary>Every line <c>Gizmos.DrawLine</c> drew so far, with the colour it was drawn in.</summary>
        internal static readonly List<(Vector3 From, Vector3 To, Color Color)> GizmoLines = new List<(Vector3, Vector3, Color)>();

        /// <summary>Keeps a warning or error (and prints it, as Unity's console shows it).</summary>
        internal static void Log(string type, object message)
        {
            Logged.Add(type + ": " + message);
            System.Console.WriteLine(type + ": " + message);
        }

        /// <summary>Connects (or with null, disconnects) a keyboard: <c>Keyboard.current</c>.</summary>
        internal static void ConnectKeyboard(bool connected) => Keyboard.StubSetCurrent(connected ? new Keyboard() : null);

        /// <summary>Clears the keys pressed this frame in both backends.</summary>
        internal static void ReleaseKeys()
        {
            LegacyKeysDown.Clear();
            InputSystemKeysDown.Clear();
        }

        /// <summary>Destroys an object (Unity defers this to the end of the frame; the stub does it at once).</summary>
        internal static void Destroy(Object obj)
        {
            if (ReferenceEquals(obj, null))
            {
                return;
            }

            if (obj is GameObject gameObject)
            {
                gameObject.transform.SetParent(null);
                MarkDestroyed(gameObject);
            }

            obj.StubDestroyed = true;
        }

        // Unity destroys a GameObject with its components, its transform and all its children.
        private static void MarkDestroyed(GameObject gameObject)
        {
            gameObject.StubDestroyed = true;
            gameObject.transform.StubDestroyed = true;
            foreach (Component component in gameObject.StubComponents)
            {
                component.StubDestroyed = true;
            }

            foreach (Transform child in gameObject.transform.StubChildren)
            {
                if (child.gameObject != null)
                {
                    MarkDestroyed(child.gameObject);
                }
            }
        }

        /// <summary>A collision with one contact (what PhysX passes to OnCollisionEnter).</summary>
        internal static Collision Collision(Vector3 point, Vector3 normal, Rigidbody other = null) =>
            new Collision { StubContacts = new[] { new ContactPoint(point, normal) }, StubRigidbody = other };

        /// <summary>
        /// One PhysX-style step of a free Rigidbody, as PhysX integrates: semi-implicit Euler in single
        /// precision, v += (g + sum of AddForce accelerations) dt; x += v dt. Clears the accumulated forces.
        /// </summary>
        internal static void SimulateStep(Rigidbody body, float dt)
        {
            Vector3 g = body.useGravity ? Physics.gravity : Vector3.zero;
            Vector3 a = g.StubPlus(body.StubAcceleration);
            body.linearVelocity = body.linearVelocity.StubPlus(body.StubVelocityChange).StubPlus(a.StubTimes(dt));
            body.position = body.position.StubPlus(body.linearVelocity.StubTimes(dt));
            body.StubAcceleration = Vector3.zero;
            body.StubVelocityChange = Vector3.zero;
        }
    }
}
