using MagnusBall.Integration.Kernels;

namespace MagnusBall
{
    // Compiled only into MagnusBall.Core.UnityCompile (ENABLE_MONO defined, as Unity defines it for its Mono backend, and
    // ENABLE_IL2CPP for IL2CPP): FlightKernel.PreferStraightLine must then come from those symbols at compile time, not
    // from the reflection lookup of Mono's marker type that Unity's managed code stripping can break. The build fails
    // when FlightKernel.CompiledForUnityBackend is missing (CS0117) or false (CS0020, a division by a constant zero).
    internal static class BackendGuard
    {
        internal const int UnityBackendChosenAtCompileTime = 1 / (FlightKernel.CompiledForUnityBackend ? 1 : 0);
    }
}
