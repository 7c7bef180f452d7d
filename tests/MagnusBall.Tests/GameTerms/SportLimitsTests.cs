using System;
using System.Linq;
using MagnusBall.Presets;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.GameTerms
{
    /// <summary>The unit-mistake guard: every preset's own ball and an ordinary shot pass; the classic slips are named.</summary>
    [TestFixture]
    public class SportLimitsTests
    {
        // An ordinary hard shot of each sport (m/s, rpm), inside the published records the limits come from.
        [TestCase("tennis", 50, 3000)]
        [TestCase("tennis-free-flight", 30, 2000)]
        [TestCase("soccer", 30, 600)]
        [TestCase("baseball", 42, 2400)]
        [TestCase("golf", 76, 2545)]
        [TestCase("golf-smits-smith", 55, 7000)]
        [TestCase("golf-bearman-harvey", 76, 2545)]
        [TestCase("golf-linear-2023", 76, 2545)]
        [TestCase("table-tennis", 20, 6000)]
        [TestCase("basketball", 8, 120)]
        public void EveryPresetsBall_AndAnOrdinaryShot_ArePlausible(string name, double speed, double rpm)
        {
            SportPreset preset = SportPresets.FromName(name);
            SportLimits limits = SportLimits.For(preset)!;
            Assert.That(limits, Is.Not.Null);
            Assert.That(limits.Check(preset.Ball.Mass, preset.Ball.Radius, speed, rpm), Is.Empty);
        }

        [Test]
        public void EveryPreset_HasLimits()
        {
            foreach (SportPreset preset in SportPresets.All)
            {
                Assert.That(SportLimits.For(preset), Is.Not.Null, preset.Name);
            }

            Assert.That(SportLimits.For(SportPresets.Tennis.WithBall(Ball.Soccer)), Is.Not.Null, "a preset keeps its sport when its ball changes");
            var custom = new SportPreset("petanque", new Ball(0.7, 0.038), null, null, null, "assumed");
            Assert.That(SportLimits.For(custom), Is.Null);
        }

        [Test]
        public void ATennisBallOfMass57_IsGramsByMistake()
        {
            string warning = SportLimits.For(SportPresets.Tennis)!.Check(57, 0.033, 30, 2000).Single();
            Assert.That(warning, Does.StartWith("mass 57 kg is outside a tennis ball's 0.056-0.0594 kg; a mass in grams?"));
            Assert.That(warning, Does.Contain("ITF Rules of Tennis"));
        }

        [Test]
        public void SpinInRpmTypedAsRadiansPerSecond_IsNamed()
        {
            // 2000 "rad/s" meant as rpm: 19,099 rpm, above any tennis ball's, while 2000 rpm is an ordinary forehand.
            string warning = SportLimits.For(SportPresets.Tennis)!.Check(0.057, 0.033, 30, Spin.ToRpm(2000)).Single();
            Assert.That(warning, Does.StartWith("spin 19098.5932 rpm (2000 rad/s) is above the most a tennis ball spins, 6000 rpm; a rate in rpm typed where rad/s is meant?"));
        }

        [Test]
        public void ADiameterForARadius_AndKilometresPerHourForMetresPerSecond_AreNamed()
        {
            var warnings = SportLimits.For(SportPresets.Soccer)!.Check(0.43, 0.22, 100, 300);
            Assert.That(warnings.Count, Is.EqualTo(2));
            Assert.That(warnings[0], Does.Contain("a diameter?"));
            Assert.That(warnings[1], Does.StartWith("speed 100 m/s is above the fastest a soccer ball flies, 60 m/s; a speed in km/h or mph?"));
        }

        [Test]
        public void TheModelAndLaunchOverload_ReadsTheBallSpeedAndSpin()
        {
            FlightModel model = SportPresets.Golf.CreateModel(Air.AtAltitude(0), Gravity.ZUp);
            var launch = new FlightState(Vector3d.Zero, new Vector3d(70, 0, 10), new Vector3d(0, -Spin.FromRpm(15000), 0));
            string warning = SportLimits.For(SportPresets.Golf)!.Check(model, launch).Single();
            Assert.That(warning, Does.StartWith("spin 15000 rpm"));
        }

        [Test]
        public void BadValues_NameTheArgument()
        {
            SportLimits limits = SportLimits.For(SportPresets.Golf)!;
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => limits.Check(0, 0.02, 10, 10))!.ParamName, Is.EqualTo("massKilograms"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => limits.Check(0.045, 0.02, double.NaN, 10))!.ParamName, Is.EqualTo("speedMetresPerSecond"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => limits.Check(0.045, 0.02, 10, -1))!.ParamName, Is.EqualTo("spinRpm"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => SportLimits.For(null!))!.ParamName, Is.EqualTo("preset"));
        }
    }
}
