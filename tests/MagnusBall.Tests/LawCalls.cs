using MagnusBall.Aerodynamics;

namespace MagnusBall.Tests
{
    /// <summary>
    /// The built-in laws implement their interface explicitly (their public surface is the interface's one method), so a
    /// test that holds a concrete law calls it through these, as the library does.
    /// </summary>
    internal static class LawCalls
    {
        public static double DragCoefficient(this IDragModel law, in AeroConditions conditions) => law.DragCoefficient(conditions);

        public static double LiftCoefficient(this ILiftModel law, in AeroConditions conditions) => law.LiftCoefficient(conditions);

        public static Vector3d SpinAcceleration(this ISpinDecayModel law, in Vector3d angularVelocity, in AeroConditions conditions) =>
            law.SpinAcceleration(angularVelocity, conditions);
    }
}
