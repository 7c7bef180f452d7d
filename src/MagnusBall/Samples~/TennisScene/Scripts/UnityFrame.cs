using MagnusBall;
using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Unity
{
    /// <summary>
    /// Moves vectors between Unity and MagnusBall. The mapping is the identity: the library runs directly in
    /// Unity's world coordinates, so there is nothing to flip.
    /// </summary>
    /// <remarks>
    /// Why no sign flip is needed in Unity's left-handed, y-up frame:
    /// - Gravity is just a vector: (0, -9.81, 0) here. The library takes "up" as -gravity and never assumes
    ///   which axis is up.
    /// - Positions and velocities are the same numbers in both worlds.
    /// - The Magnus force points along w x v. The cross product is the same determinant formula in Unity
    ///   (Vector3.Cross) and in the library (Vector3d.Cross). In a left-handed frame the rotation vector of a
    ///   spinning ball follows the left-hand rule (Unity's convention for angular velocity and for
    ///   Quaternion.AngleAxis), and the two conventions cancel: w x v still points where the real force
    ///   points. The thesis's scene used the same left-hand rule for its spin inputs (Agrawal 2023, 3.2-3.3).
    /// - To avoid thinking about handedness at all, build spin by its effect: Spin.Topspin(v, up, rate),
    ///   Spin.Backspin and Spin.Toward(v, direction, rate) give w = rate normalize(v x d), which curves the
    ///   ball toward d in any handedness (tests/MagnusBall.Tests/Behavior/SpinSignTests.cs checks this in
    ///   z-up right-handed, Unity and Godot frames).
    /// Only the precision changes: Unity stores float, the library double. Convert at the edge, once per
    /// frame, and keep the simulation in double.
    /// </remarks>
    public static class UnityFrame
    {
        /// <summary>A Unity vector as a library vector (same components).</summary>
        /// <param name="v">Unity vector.</param>
        public static Vector3d ToLibrary(Vector3 v) => new Vector3d(v.x, v.y, v.z);

        /// <summary>A library vector as a Unity vector (same components, rounded to float).</summary>
        /// <param name="v">Library vector.</param>
        public static Vector3 ToUnity(Vector3d v) => new Vector3((float)v.X, (float)v.Y, (float)v.Z);
    }
}
