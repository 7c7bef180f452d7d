using System;

namespace MagnusBall
{
    /// <summary>
    /// The one rule by which the library finds a thing by name (an integrator, a sport preset, a surface):
    /// case-insensitive, surrounding white space ignored, and '_' or ' ' standing for '-' ("Stable_RK4", " table tennis").
    /// </summary>
    internal static class NameLookup
    {
        /// <summary>True when <paramref name="given"/> names <paramref name="canonical"/> (a lower-case, hyphenated name).</summary>
        internal static bool Matches(string canonical, string? given) =>
            given != null && string.Equals(canonical, Normalize(given), StringComparison.OrdinalIgnoreCase);

        private static string Normalize(string name) => name.Trim().Replace('_', '-').Replace(' ', '-');
    }
}
