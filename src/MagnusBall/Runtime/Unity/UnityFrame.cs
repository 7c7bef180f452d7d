#nullable enable
using System;
using UnityEngine;

namespace MagnusBall.Components
{
    /// <summary>
    /// Moves vectors between Unity and MagnusBall. The mapping is the identity: the library runs directly in
    /// Unity's world coordinates (y-up, left-handed), so there is nothing to flip.
    /// </summary>
    /// <remarks>
    /// Why no sign flip is needed in Unity's left-handed, y-up frame:
    /// - Gravity is just a vector: <see cref="Gravity.YUp"/>, (0, -9.80665, 0). The library takes "up" as
    ///   -gravity and never assumes which axis is up.
    /// - Positions and velocities are the same numbers in both worlds.
    /// - The Magnus force points along w x v. The cross product is the same determinant formula in Unity
    ///   and in the library. In a left-handed frame the rotation vector of a spinning ball follows the
    ///   left-hand rule (Unity's convention for angular velocity and for Quaternion.AngleAxis), and the two
    ///   conventions cancel: w x v still points where the real force points.
    /// - To avoid thinking about handedness at all, build spin by its effect: <see cref="Spin.Topspin"/>,
    ///   <see cref="Spin.Backspin"/> and <see cref="Spin.Toward"/> curve the ball toward the direction given
    ///   in any handedness (tests/MagnusBall.Tests/Behavior/SpinSignTests.cs).
    /// Only the precision changes: Unity stores float, the library double. Convert at the edge and keep the
    /// simulation in double; float to double is exact, double to float rounds.
    /// </remarks>
    public static class UnityFrame
    {
        /// <summary>A Unity vector as a library vector (same components, exactly).</summary>
        /// <param name="v">Unity vector.</param>
        public static Vector3d ToLibrary(Vector3 v) => new Vector3d(v.x, v.y, v.z);

        /// <summary>A library vector as a Unity vector (same components, rounded to float).</summary>
        /// <param name="v">Library vector.</param>
        public static Vector3 ToUnity(Vector3d v) => new Vector3((float)v.X, (float)v.Y, (float)v.Z);

        /// <summary>The package's manual (the components' [HelpURL] pages point into it).</summary>
        internal const string ManualUrl = "https://github.com/magnusball/MagnusBall/blob/main/src/MagnusBall/Documentation~/MagnusBall.md";

        /// <summary>
        /// Reports an inspector value a component refused (OnValidate) with <c>Debug.LogError</c>, naming the field, unless it is
        /// the problem reported last (<paramref name="last"/>): each problem once, not at every edit or load.
        /// </summary>
        internal static void ReportRefusal(ref string? last, Component component, ArgumentException refusal)
        {
            string message = $"{component.GetType().Name} on '{component.name}': {refusal.ParamName} refused: {refusal.Message} The previous settings stay in use.";
            if (message != last)
            {
                last = message;
                Debug.LogError(message, component);
            }
        }

        /// <summary>Unity's up, +y: the opposite of <see cref="Gravity.YUp"/>.</summary>
        public static Vector3d Up => new Vector3d(0, 1, 0);
    }
}
