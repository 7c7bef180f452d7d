using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Xml.Linq;
using NUnit.Framework;

namespace MagnusBall.Tests.Api
{
    /// <summary>
    /// Every public constructor of the library has XML docs. The build's CS1591 (an error here) covers what the
    /// source declares, but not the constructor the compiler adds to a class that declares none: nine
    /// stateless laws and integrators (RungeKutta4, StepanekDrag, ...) had a public, undocumented one.
    /// </summary>
    [TestFixture]
    public class XmlDocTests
    {
        [Test]
        public void EveryPublicConstructor_HasXmlDocs()
        {
            Assembly library = typeof(Ball).Assembly;
            string xml = Path.ChangeExtension(library.Location, ".xml");
            Assert.That(File.Exists(xml), Is.True, $"the library's documentation file beside it: {xml}");
            var documented = new HashSet<string>(
                XDocument.Load(xml).Descendants("member").Select(m => (string)m.Attribute("name")!), StringComparer.Ordinal);

            var missing = new List<string>();
            foreach (Type type in library.GetExportedTypes().Where(t => !t.IsValueType && !t.IsInterface && !t.IsGenericTypeDefinition))
            {
                foreach (ConstructorInfo ctor in type.GetConstructors(BindingFlags.Public | BindingFlags.Instance))
                {
                    // The documentation ID of a constructor: M:Namespace.Type.#ctor(ParameterType,...); nested types
                    // joined by '.'. Constructors with generic, by-ref or array parameters are declared in source
                    // (CS1591 covers them); only the parameterless one can be compiler-generated.
                    if (ctor.GetParameters().Length == 0)
                    {
                        string id = "M:" + type.FullName!.Replace('+', '.') + ".#ctor";
                        if (!documented.Contains(id))
                        {
                            missing.Add(id);
                        }
                    }
                }
            }

            Assert.That(missing, Is.Empty, "public constructors without XML docs (declare and document them):\n" + string.Join("\n", missing));
        }
    }
}
