using System;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Api
{
    /// <summary>The three lookups by name (integrators, presets, surfaces) follow one rule.</summary>
    [TestFixture]
    public class NameLookupTests
    {
        [Test]
        public void EveryLookup_IgnoresCase_SpacesAround_AndTakesUnderscoreOrSpaceForHyphen()
        {
            Assert.That(Integrators.FromName(" Stable_RK4 "), Is.SameAs(StableIntegrator.RungeKutta4));
            Assert.That(Integrators.FromName("semi implicit euler").Name, Is.EqualTo("semi-implicit-euler"));
            Assert.That(SportPresets.FromName(" Table_Tennis").Name, Is.EqualTo("table-tennis"));
            Assert.That(SportPresets.FromName("GOLF-smits smith").Name, Is.EqualTo("golf-smits-smith"));
            Assert.That(Surface.FromName(" Clay "), Is.SameAs(Surface.Clay));
        }

        [Test]
        public void UnknownOrNullNames_AreRefused_NamingTheParameter()
        {
            Assert.That(Assert.Throws<ArgumentException>(() => Integrators.FromName("rk5"))!.ParamName, Is.EqualTo("name"));
            Assert.That(Assert.Throws<ArgumentException>(() => Integrators.FromName(null!))!.ParamName, Is.EqualTo("name"));
            Assert.That(Assert.Throws<ArgumentException>(() => SportPresets.FromName("cricket"))!.ParamName, Is.EqualTo("name"));
            Assert.That(Assert.Throws<ArgumentException>(() => Surface.FromName(null!))!.ParamName, Is.EqualTo("name"));
            Assert.That(Assert.Throws<ArgumentException>(() => Surface.FromName("ice"))!.ParamName, Is.EqualTo("name"));
        }
    }
}
