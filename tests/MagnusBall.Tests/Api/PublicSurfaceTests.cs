using System.Linq;
using System.Reflection;
using NUnit.Framework;

namespace MagnusBall.Tests.Api
{
    /// <summary>
    /// The library's public surface stays small (issue 38: at most 460 members in the ten namespaces it had then). A member
    /// is a constructor, method, property, field or event declared on an exported type; a property's or event's accessors are
    /// folded into it, and an enum's hidden value__ field is not counted. Anything the CLI, benchmarks or tests need that a
    /// game does not goes through InternalsVisibleTo.
    /// </summary>
    public class PublicSurfaceTests
    {
        private static readonly string[] TenNamespaces =
        {
            "MagnusBall", "MagnusBall.Aerodynamics", "MagnusBall.Batch", "MagnusBall.Contact", "MagnusBall.Contact.Swings",
            "MagnusBall.Flight", "MagnusBall.Integration", "MagnusBall.Presets", "MagnusBall.Queries", "MagnusBall.Stepping",
        };

        internal static int CountMembers(Assembly assembly, string[] namespaces)
        {
            const BindingFlags declared = BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
            return assembly.GetExportedTypes()
                .Where(t => namespaces.Contains(t.Namespace))
                .Sum(t => t.GetMembers(declared).Count(m =>
                    !(m is System.Type) &&
                    m.Name != "value__" &&
                    !(m is MethodInfo method && method.IsSpecialName &&
                      (method.Name.StartsWith("get_") || method.Name.StartsWith("set_") ||
                       method.Name.StartsWith("add_") || method.Name.StartsWith("remove_")))));
        }

        [Test]
        public void PublicMembers_InTheTenNamespaces_AtMost460()
        {
            int count = CountMembers(typeof(FlightModel).Assembly, TenNamespaces);
            Assert.That(count, Is.LessThanOrEqualTo(460),
                "Each public member is a promise to users: make what only the CLI, benchmarks or tests need internal.");
        }
    }
}
