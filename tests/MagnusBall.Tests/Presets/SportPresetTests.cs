using System;
using System.Linq;
using MagnusBall.Contact;
using MagnusBall.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Presets
{
    /// <summary>The preset catalogue: lookup by name, sources, overrides.</summary>
    [TestFixture]
    public class SportPresetTests
    {
        [Test]
        public void FromName_FindsEveryPreset_IgnoringCaseAndSeparators()
        {
            foreach (SportPreset preset in SportPresets.All)
            {
                Assert.That(SportPresets.FromName(preset.Name), Is.SameAs(preset));
                Assert.That(SportPresets.FromName(preset.Name.ToUpperInvariant()), Is.SameAs(preset));
            }

            Assert.That(SportPresets.FromName("Table_Tennis"), Is.SameAs(SportPresets.TableTennis));
            Assert.That(SportPresets.FromName(" table tennis "), Is.SameAs(SportPresets.TableTennis));
            Assert.That(SportPresets.Names, Is.EquivalentTo(new[]
            {
                "tennis", "tennis-free-flight", "soccer", "baseball", "golf", "golf-smits-smith", "table-tennis", "basketball", "golf-bearman-harvey", "golf-linear-2023",
            }));
        }

        [TestCase("cricket")]
        [TestCase("")]
        [TestCase(null)]
        public void FromName_RefusesAnUnknownName_ListingTheKnownOnes(string? name)
        {
            var error = Assert.Throws<ArgumentException>(() => SportPresets.FromName(name!));
            Assert.That(error!.ParamName, Is.EqualTo("name"));
            foreach (string known in SportPresets.Names)
            {
                Assert.That(error.Message, Does.Contain(known));
            }
        }

        [Test]
        public void EveryPreset_CitesASource_AndBuildsAWorkingModel()
        {
            foreach (SportPreset preset in SportPresets.All)
            {
                Assert.That(preset.Source, Does.Match("[0-9]{4}|ITF|FIFA|MLB|USGA|ITTF|FIBA"), preset.Name);
                FlightModel model = preset.CreateModel(Air.SeaLevel, Gravity.YUp);
                StateDerivative d = model.Derivative(new FlightState(Vector3d.Zero, new Vector3d(20, 5, 0), new Vector3d(0, 0, 100)));
                Assert.That(d.Acceleration.IsFinite && d.AngularAcceleration.IsFinite, Is.True, preset.Name);
                Assert.That(model.Drag, Is.Not.Null, preset.Name);
                Assert.That(model.Lift, Is.Not.Null, preset.Name);
            }
        }

        [Test]
        public void BallsMatchTheirRulebooks()
        {
            // Rulebook ranges (ITF, FIFA size 5, MLB, USGA limits, ITTF, FIBA size 7).
            Assert.That(SportPresets.Tennis.Ball.Mass, Is.InRange(0.0560, 0.0594));
            Assert.That(2 * SportPresets.Tennis.Ball.Radius, Is.InRange(0.0654, 0.0686));
            Assert.That(SportPresets.Soccer.Ball.Mass, Is.InRange(0.410, 0.450));
            Assert.That(2 * Math.PI * SportPresets.Soccer.Ball.Radius, Is.InRange(0.68, 0.70));
            Assert.That(SportPresets.Baseball.Ball.Mass, Is.InRange(0.1417, 0.1488));
            Assert.That(2 * Math.PI * SportPresets.Baseball.Ball.Radius, Is.InRange(0.2286, 0.2350));
            Assert.That(SportPresets.Golf.Ball.Mass, Is.LessThanOrEqualTo(0.04593));
            Assert.That(2 * SportPresets.Golf.Ball.Radius, Is.GreaterThanOrEqualTo(0.04267));
            Assert.That(SportPresets.TableTennis.Ball.Mass, Is.EqualTo(0.0027));
            Assert.That(2 * SportPresets.TableTennis.Ball.Radius, Is.EqualTo(0.040));
            Assert.That(SportPresets.Basketball.Ball.Mass, Is.InRange(0.567, 0.650));
            Assert.That(2 * Math.PI * SportPresets.Basketball.Ball.Radius, Is.InRange(0.749, 0.780));
        }

        [Test]
        public void EveryPreset_StepsWithoutAllocating()
        {
            foreach (SportPreset preset in SportPresets.All)
            {
                FlightModel model = preset.CreateModel(Air.SeaLevel.WithLogarithmicWind(new Vector3d(3, 0, 1)), Gravity.YUp);
                var start = new FlightState(new Vector3d(0, 1, 0), new Vector3d(25, 8, 1), new Vector3d(50, 10, 300));
                FlightState end = default;
                Action fly = () => end = Shots.Fly(model, MagnusBall.Integration.RungeKutta4.Instance, start, 1e-3, 2000);
                long allocated = Allocation.SteadyStateBytes(fly);
                Assert.That(allocated, Is.EqualTo(0), preset.Name);
                Assert.That(end.IsFinite, Is.True, preset.Name);
            }
        }

        [Test]
        public void BadPresetArguments_AreRefusedNamingTheParameter()
        {
            Assert.That(() => new SportPreset("", Ball.Tennis, null, null, null, "x 2000"), Throws.InstanceOf<ArgumentException>().With.Property("ParamName").EqualTo("name"));
            Assert.That(() => new SportPreset("x", null!, null, null, null, "x 2000"), Throws.InstanceOf<ArgumentException>().With.Property("ParamName").EqualTo("ball"));
            Assert.That(() => new SportPreset("x", Ball.Tennis, null, null, null, " "), Throws.InstanceOf<ArgumentException>().With.Property("ParamName").EqualTo("source"));
            Assert.That(() => SportPresets.Golf.CreateModel(null!, Gravity.ZUp), Throws.InstanceOf<ArgumentException>().With.Property("ParamName").EqualTo("air"));
        }

        [Test]
        public void Overrides_ReplaceOnePartAndKeepTheRest()
        {
            SportPreset golf = SportPresets.Golf;
            SportPreset noDecay = golf.WithSpinDecay(null);
            Assert.That(noDecay.SpinDecay, Is.Null);
            Assert.That(noDecay.Drag, Is.SameAs(golf.Drag));
            Assert.That(noDecay.Lift, Is.SameAs(golf.Lift));
            Assert.That(noDecay.Ball, Is.SameAs(golf.Ball));
            Assert.That(noDecay.Name, Is.EqualTo("golf"));
            Assert.That(golf.WithBall(Ball.Tennis).Ball, Is.SameAs(Ball.Tennis));
            Assert.That(SportPresets.All.Select(p => p.Name).Distinct().Count(), Is.EqualTo(SportPresets.All.Count));
        }

        [Test]
        public void TennisPresets_BounceOnAHardCourt_AndOverridesKeepTheBounce()
        {
            Assert.That(SportPresets.Tennis.Bounce, Is.SameAs(CrossBounce.Hard));
            Assert.That(SportPresets.TennisFreeFlight.Bounce, Is.SameAs(CrossBounce.Hard));
            Assert.That(SportPresets.Tennis.WithDrag(null).Bounce, Is.SameAs(CrossBounce.Hard));
            Assert.That(SportPresets.Tennis.WithBounce(CrossBounce.Clay).Bounce, Is.SameAs(CrossBounce.Clay));
            Assert.That(SportPresets.Golf.Bounce, Is.Null, "no golf bounce model is sourced");

            // The default bounce is a real one: a 25 m/s, 16 degree ball without spin slides and leaves at
            // 15.81 m/s (docs/references.md section 5, worked hard-court case).
            double a = 16 * System.Math.PI / 180;
            BounceOutcome outcome = SportPresets.Tennis.Bounce!.Bounce(
                new Ball(0.057, 0.033, 0.55), Vector3d.UnitZ, new Vector3d(25 * System.Math.Cos(a), 0, -25 * System.Math.Sin(a)), Vector3d.Zero);
            // 0.005 m/s: half the last digit of the published 15.81.
            Assert.That(outcome.Velocity.Length, Is.EqualTo(15.81).Within(0.005));
        }
    }
}
