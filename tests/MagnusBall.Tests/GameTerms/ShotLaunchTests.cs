using System;
using MagnusBall.Presets;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.GameTerms
{
    /// <summary>Launches in game terms: units, angles from forward, spin by effect, TrackMan's and Statcast's axes, any frame.</summary>
    [TestFixture]
    public class ShotLaunchTests
    {
        private static ShotFlyer Tennis(bool yUp) => yUp
            ? new ShotFlyer(SportPresets.Tennis.CreateModel(Air.AtAltitude(0), Gravity.YUp), ShotFrame.YUp)
            : new ShotFlyer(SportPresets.Tennis.CreateModel(Air.AtAltitude(0), Gravity.ZUp), ShotFrame.ZUp);

        [Test]
        public void Speeds_ConvertExactly()
        {
            // 1 mph = 0.44704 m/s and 1 km/h = 1/3.6 m/s by definition; the tolerance is the last bits of the division.
            Assert.That(Speed.FromMilesPerHour(100).MetresPerSecond, Is.EqualTo(44.704).Within(1e-12));
            Assert.That(Speed.FromKilometresPerHour(36).MetresPerSecond, Is.EqualTo(10).Within(1e-12));
            Assert.That(Speed.FromMetresPerSecond(30).MetresPerSecond, Is.EqualTo(30));
        }

        [Test]
        public void TheSameShot_FliesTheSame_InZUp_UnitysYUp_AndGodotsYUp()
        {
            // Up, forward and right are axes of either frame, so the two flights are the same arithmetic on permuted
            // components: equal to rounding (1e-9 m on a 20 m flight leaves room for a different order of sums).
            ShotLaunch launch = ShotLaunch.ByEffect(Speed.FromKilometresPerHour(120), 8, directionDegrees: 5, topspinRpm: 2500, sidespinRpm: 800);
            FlightSummary z = Tennis(false).Fly(launch, -0.5, 0, 1);
            FlightSummary y = Tennis(true).Fly(launch, -0.5, 0, 1);
            // Godot: right-handed y-up, forward -z, right +x, with the origin moved off zero.
            var godotFrame = new ShotFrame(Vector3d.UnitY, -Vector3d.UnitZ, Vector3d.UnitX, new Vector3d(3, 0, -7));
            FlightSummary g = new ShotFlyer(SportPresets.Tennis.CreateModel(Air.AtAltitude(0), Gravity.YUp), godotFrame).Fly(launch, -0.5, 0, 1);
            Assert.Multiple(() =>
            {
                Assert.That(g.CarryMetres, Is.EqualTo(z.CarryMetres).Within(1e-9));
                Assert.That(g.CurveMetres, Is.EqualTo(z.CurveMetres).Within(1e-9));
                Assert.That(y.CarryMetres, Is.EqualTo(z.CarryMetres).Within(1e-9));
                Assert.That(y.SideMetres, Is.EqualTo(z.SideMetres).Within(1e-9));
                Assert.That(y.CurveMetres, Is.EqualTo(z.CurveMetres).Within(1e-9));
                Assert.That(y.ApexMetres, Is.EqualTo(z.ApexMetres).Within(1e-9));
                Assert.That(z.SideMetres, Is.GreaterThan(0), "aimed 5 degrees right with sidespin to the right");
                Assert.That(z.CurveMetres, Is.GreaterThan(0), "positive sidespin curves right");
            });
        }

        [Test]
        public void DirectionAndSidespin_PointRight_InBothHandednesses()
        {
            // z-up, right-handed: right is -y. Unity's y-up, left-handed: right is +x.
            ShotLaunch right = ShotLaunch.ByEffect(Speed.FromMetresPerSecond(25), 10, directionDegrees: 10);
            var zUp = Tennis(false);
            FlightState z = zUp.LaunchState(right, 0, 0, 1);
            FlightState y = Tennis(true).LaunchState(right, 0, 0, 1);
            Assert.That(z.Velocity.Y, Is.LessThan(0));
            Assert.That(y.Velocity.X, Is.GreaterThan(0));
            FlightSummary curl = zUp.Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(25), 10, sidespinRpm: -1500), 0, 0, 1);
            Assert.That(curl.CurveMetres, Is.LessThan(0), "negative sidespin curves left");
            Assert.That(curl.SideMetres, Is.EqualTo(curl.CurveMetres).Within(1e-12), "launched straight: side and curve agree");
        }

        [Test]
        public void Topspin_Dips_Backspin_Floats()
        {
            var flyer = Tennis(false);
            double flat = flyer.Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(25), 8), 0, 0, 1).CarryMetres;
            double top = flyer.Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(25), 8, topspinRpm: 2000), 0, 0, 1).CarryMetres;
            double back = flyer.Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(25), 8, topspinRpm: -2000), 0, 0, 1).CarryMetres;
            Assert.That(top, Is.LessThan(flat));
            Assert.That(back, Is.GreaterThan(flat));
        }

        [Test]
        public void TrackMansSpinAxis_SplitsTheSpin_IntoBackspinAndSidespin()
        {
            ShotLaunch launch = ShotLaunch.TrackMan(Speed.FromMilesPerHour(171), 10.4, 0, 2545, spinAxisDegrees: 30);
            Assert.Multiple(() =>
            {
                Assert.That(launch.TopspinRpm, Is.EqualTo(-2545 * Math.Cos(Math.PI / 6)).Within(1e-9));
                Assert.That(launch.SidespinRpm, Is.EqualTo(2545 * 0.5).Within(1e-9));
                Assert.That(launch.GyroRpm, Is.EqualTo(0));
            });
        }

        [TestCase("12:00", 180)]
        [TestCase("6:00", 0)]
        [TestCase("1:30", 225)]
        [TestCase("9:00", 90)]
        [TestCase("3:00", 270)]
        public void StatcastsClock_IsItsAxis(string clock, double degrees)
        {
            ShotLaunch byClock = ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, 2000, clock);
            ShotLaunch byDegrees = ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, 2000, degrees);
            Assert.That(byClock.TopspinRpm, Is.EqualTo(byDegrees.TopspinRpm).Within(1e-9));
            Assert.That(byClock.SidespinRpm, Is.EqualTo(byDegrees.SidespinRpm).Within(1e-9));
        }

        [Test]
        public void StatcastsAxis_180IsBackspin_0IsTopspin_270CurvesToThePitchersRight()
        {
            // Savant: 180 is a pure backspin fastball, 0 a pure topspin (12-6) curveball; 3:00 (270) moves toward the
            // third-base side, which is the right of a pitcher facing the plate. Rounding of cos/sin at these angles: 1e-9 rpm.
            Assert.That(ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, 2000, 180).TopspinRpm, Is.EqualTo(-2000).Within(1e-9));
            Assert.That(ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, 2000, 0).TopspinRpm, Is.EqualTo(2000).Within(1e-9));
            Assert.That(ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, 2000, 270).SidespinRpm, Is.EqualTo(2000).Within(1e-9));
        }

        [Test]
        public void SpinEfficiency_LeavesTheRestAsGyroSpin()
        {
            ShotLaunch launch = ShotLaunch.Statcast(Speed.FromMilesPerHour(80), 0, 0, 2500, 0, spinEfficiency: 0.6);
            Assert.That(launch.TopspinRpm, Is.EqualTo(1500).Within(1e-9));
            Assert.That(launch.GyroRpm, Is.EqualTo(2000).Within(1e-9), "0.6^2 + 0.8^2 = 1");
            FlightState state = new ShotFlyer(SportPresets.Baseball.CreateModel(Air.AtAltitude(0), Gravity.ZUp), ShotFrame.ZUp).LaunchState(launch, 0, 0, 2);
            Assert.That(Spin.ToRpm(state.AngularVelocity.Length), Is.EqualTo(2500).Within(1e-9), "the whole rate is kept");
        }

        [TestCase("13:00")]
        [TestCase("0:30")]
        [TestCase("1:3")]
        [TestCase("1:60")]
        [TestCase("one thirty")]
        [TestCase("")]
        [TestCase(null)]
        public void BadClock_NamesTheClock(string? clock)
        {
            var e = Assert.Throws<ArgumentException>(() => ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, 2000, clock!));
            Assert.That(e!.ParamName, Is.EqualTo("spinAxisClock"));
            Assert.That(e.Message, Does.Contain("h:mm"));
        }

        [Test]
        public void BadValues_NameTheArgumentAndRange()
        {
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ShotLaunch.ByEffect(Speed.FromMetresPerSecond(10), 91))!.ParamName, Is.EqualTo("elevationDegrees"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ShotLaunch.ByEffect(Speed.FromMetresPerSecond(10), 5, 181))!.ParamName, Is.EqualTo("directionDegrees"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ShotLaunch.ByEffect(Speed.FromMetresPerSecond(10), 5, 0, double.NaN))!.ParamName, Is.EqualTo("topspinRpm"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => Speed.FromMilesPerHour(-1))!.ParamName, Is.EqualTo("milesPerHour"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ShotLaunch.TrackMan(Speed.FromMilesPerHour(100), 10, 0, 2000, 95))!.ParamName, Is.EqualTo("spinAxisDegrees"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, 2000, 180, 1.5))!.ParamName, Is.EqualTo("spinEfficiency"));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => ShotLaunch.ByEffect(Speed.FromMetresPerSecond(10), 91));
            Assert.That(e!.Message, Does.Contain("[-90, 90]"));
        }

        [Test]
        public void BadFrames_AreRefused()
        {
            Assert.That(Assert.Throws<ArgumentException>(() => new ShotFrame(Vector3d.UnitZ, Vector3d.UnitX, Vector3d.UnitX))!.ParamName, Is.EqualTo("right"));
            Assert.That(Assert.Throws<ArgumentException>(() => new ShotFrame(Vector3d.UnitZ, Vector3d.UnitZ, Vector3d.UnitY))!.ParamName, Is.EqualTo("forward"));
            FlightModel zUp = SportPresets.Golf.CreateModel(Air.AtAltitude(0), Gravity.ZUp);
            Assert.That(Assert.Throws<ArgumentException>(() => new ShotFlyer(zUp, ShotFrame.YUp))!.ParamName, Is.EqualTo("frame"));
            Assert.That(Assert.Throws<ArgumentException>(() => new ShotFlyer(zUp, default))!.ParamName, Is.EqualTo("frame"));
        }

        [Test]
        public void AFrameKeepsOnlyTheSideOfRight_AndPlacesPointsFromItsOrigin()
        {
            var frame = new ShotFrame(new Vector3d(0, 0, 2), new Vector3d(1, 0, 0.5), new Vector3d(0.3, -4, 1), new Vector3d(10, 20, 0));
            Assert.That(frame.Right, Is.EqualTo(new Vector3d(0, -1, 0)));
            Assert.That(frame.At(1, 2, 3), Is.EqualTo(new Vector3d(11, 18, 3)));
        }
    }
}
