// The library's struct-heavy step code (states, derivatives and Hermite segments held as locals) skips the zeroing of its
// stack frames on entry: C#'s definite assignment already guarantees that no local is read before it is written, and no
// method here uses stackalloc, so nothing a method computes changes. Before, the JIT cleared over 1 kB of frame on every
// FlightStepper.TryStep call (docs/performance.md).
//
// Unity's compiler refuses this C# 9 feature ("Suppress emitting localsinit flag" is on its list of unsupported features,
// and it needs unsafe code switched on), so the package's sources compiled by Unity leave it out: every Unity version since
// 5.3 defines UNITY_5_3_OR_NEWER. The DLL built by dotnet (MagnusBall.csproj: AllowUnsafeBlocks) keeps it; its IL runs on
// Unity's Mono and IL2CPP unchanged. tests/MagnusBall.Core.UnityCompile compiles the core as Unity does.
#if !UNITY_5_3_OR_NEWER
[module: System.Runtime.CompilerServices.SkipLocalsInit]

namespace System.Runtime.CompilerServices
{
    /// <summary>
    /// The compiler's marker to omit the "zero every local" flag (defined here: netstandard2.1 lacks it; the C# compiler
    /// recognises it by name).
    /// </summary>
    [AttributeUsage(AttributeTargets.Module | AttributeTargets.Class | AttributeTargets.Struct | AttributeTargets.Method
        | AttributeTargets.Constructor | AttributeTargets.Property | AttributeTargets.Event | AttributeTargets.Interface, Inherited = false)]
    internal sealed class SkipLocalsInitAttribute : Attribute
    {
    }
}
#endif
