using System;
using System.Collections.Generic;
using MagnusBall.Contact;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>Bad arguments to the contact API are refused, naming the parameter.</summary>
    [TestFixture]
    public class ContactBadInputTests
    {
        private static readonly Vector3d Down = new Vector3d(10, 0, -5);

        public static IEnumerable<TestCaseData> Cases()
        {
            yield return new TestCaseData("normalRestitution", (TestDelegate)(() => new Surface("x", 1.1, 0, 0.5, 0.1, 0, 0))).SetName("e_y above 1");
            yield return new TestCaseData("normalRestitution", (TestDelegate)(() => new Surface("x", double.NaN, 0, 0.5, 0.1, 0, 0))).SetName("e_y NaN");
            yield return new TestCaseData("normalRestitutionPerDegree", (TestDelegate)(() => new Surface("x", 0.9, double.PositiveInfinity, 0.5, 0.1, 0, 0))).SetName("slope infinite");
            yield return new TestCaseData("slidingFriction", (TestDelegate)(() => new Surface("x", 0.9, 0, -0.1, 0.1, 0, 0))).SetName("mu negative");
            yield return new TestCaseData("tangentialRestitution", (TestDelegate)(() => new Surface("x", 0.9, 0, 0.5, -0.1, 0, 0))).SetName("e_x negative");
            yield return new TestCaseData("forceOffset", (TestDelegate)(() => new Surface("x", 0.9, 0, 0.5, 0.1, -1e-3, 0))).SetName("D negative");
            yield return new TestCaseData("forceOffsetPerSpeed", (TestDelegate)(() => new Surface("x", 0.9, 0, 0.5, 0.1, 0, double.NaN))).SetName("D per speed NaN");
            yield return new TestCaseData("name", (TestDelegate)(() => new Surface(null!, 0.9, 0, 0.5, 0.1, 0, 0))).SetName("name null");
            yield return new TestCaseData("name", (TestDelegate)(() => Surface.FromName("ice"))).SetName("unknown surface");
            yield return new TestCaseData("surface", (TestDelegate)(() => new CrossBounce(null!))).SetName("surface null");
            yield return new TestCaseData("ball", (TestDelegate)(() => CrossBounce.Hard.Bounce(null!, Vector3d.UnitZ, Down, default))).SetName("ball null");
            yield return new TestCaseData("normal", (TestDelegate)(() => CrossBounce.Hard.Bounce(Ball.Tennis, Vector3d.Zero, Down, default))).SetName("normal zero");
            yield return new TestCaseData("normal", (TestDelegate)(() => CrossBounce.Hard.Bounce(Ball.Tennis, new Vector3d(0, double.NaN, 1), Down, default))).SetName("normal NaN");
            yield return new TestCaseData("velocity", (TestDelegate)(() => CrossBounce.Hard.Bounce(Ball.Tennis, Vector3d.UnitZ, new Vector3d(double.PositiveInfinity, 0, -1), default))).SetName("velocity infinite");
            yield return new TestCaseData("angularVelocity", (TestDelegate)(() => CrossBounce.Hard.Bounce(Ball.Tennis, Vector3d.UnitZ, Down, new Vector3d(0, double.NaN, 0)))).SetName("spin NaN");
        }

        [TestCaseSource(nameof(Cases))]
        public void IsRefused_NamingTheParameter(string parameter, TestDelegate action)
        {
            var e = Assert.Throws(Is.InstanceOf<ArgumentException>(), action)!;
            Assert.That(((ArgumentException)e).ParamName, Is.EqualTo(parameter));
            Assert.That(e.Message, Does.Contain(parameter));
        }

        [Test]
        public void Presets_AreFoundByName()
        {
            foreach (Surface s in Surface.All)
            {
                Assert.That(Surface.FromName(s.Name.ToUpperInvariant()), Is.SameAs(s));
            }
        }
    }
}
