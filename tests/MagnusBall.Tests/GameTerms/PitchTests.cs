using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Presets;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.GameTerms
{
    /// <summary>A pitch's plate crossing and break (Statcast's terms), against a circle and against the signs of Statcast's axes.</summary>
    [TestFixture]
    public class PitchTests
    {
        private static ShotFlyer Baseball(bool yUp = false) => yUp
            ? new ShotFlyer(SportPresets.Baseball.CreateModel(Air.AtAltitude(0), Gravity.YUp), ShotFrame.YUp)
            : new ShotFlyer(SportPresets.Baseball.CreateModel(Air.AtAltitude(0), Gravity.ZUp), ShotFrame.ZUp);

        private static PitchResult Pitch(ShotFlyer flyer, string clock, double rpm = 2400) =>
            flyer.Pitch(ShotLaunch.Statcast(Speed.FromMilesPerHour(90), 0, 0, rpm, clock), 1.8, 0, 1.8);

        [Test]
        public void WithoutSpin_ThereIsNoBreak()
        {
            PitchResult p = Pitch(Baseball(), "12:00", rpm: 0);
            Assert.That(p.CrossesPlate, Is.True);
            Assert.That(p.InducedVerticalBreakInches, Is.EqualTo(0).Within(1e-9));
            Assert.That(p.HorizontalBreakInches, Is.EqualTo(0).Within(1e-9));
        }

        [Test]
        public void TheBreak_FollowsStatcastsAxis()
        {
            ShotFlyer flyer = Baseball();
            Assert.Multiple(() =>
            {
                Assert.That(Pitch(flyer, "12:00").InducedVerticalBreakInches, Is.GreaterThan(5), "backspin rises against a spinless pitch");
                Assert.That(Pitch(flyer, "12:00").HorizontalBreakInches, Is.EqualTo(0).Within(1e-9), "straight down the middle");
                Assert.That(Pitch(flyer, "6:00").InducedVerticalBreakInches, Is.LessThan(-5), "topspin drops");
                Assert.That(Pitch(flyer, "9:00").HorizontalBreakInches, Is.GreaterThan(5), "toward the first-base side: the catcher's right");
                Assert.That(Pitch(flyer, "3:00").HorizontalBreakInches, Is.LessThan(-5));
            });
        }

        [Test]
        public void ThePitch_IsTheSame_InZUpAndYUp()
        {
            ShotLaunch curve = ShotLaunch.Statcast(Speed.FromMilesPerHour(79), 1.5, -1, 2600, "7:00", 0.6);
            PitchResult z = Baseball().Pitch(curve, 1.83, 0.5, 1.8), y = Baseball(yUp: true).Pitch(curve, 1.83, 0.5, 1.8);
            Assert.That(y.InducedVerticalBreakInches, Is.EqualTo(z.InducedVerticalBreakInches).Within(1e-7));
            Assert.That(y.HorizontalBreakInches, Is.EqualTo(z.HorizontalBreakInches).Within(1e-7));
            Assert.That(y.PlateHeightFeet, Is.EqualTo(z.PlateHeightFeet).Within(1e-9));
            Assert.That(y.PlateSideFeet, Is.EqualTo(z.PlateSideFeet).Within(1e-9));
        }

        [Test]
        public void ConstantLiftWithoutGravityOrDrag_BendsThePitchOnACircle()
        {
            // No gravity, no drag, a constant C_L across the flight: the ball keeps its speed v and turns on a circle of
            // radius R = v^2 / a, a = rho A C_L v^2 / (2 m). Launched level along forward, it meets the plate's front, L ahead,
            // R - sqrt(R^2 - L^2) above the spinless straight line. RK4 at 1/240 s follows this circle to 1e-9 m here.
            Ball ball = SportPresets.Baseball.Ball;
            var air = new Air(1.2);
            var model = new FlightModel(ball, air, Vector3d.Zero, null, new ConstantLift(0.2));
            var flyer = new ShotFlyer(model, ShotFrame.ZUp);
            double v = 40, release = 1.8;
            PitchResult p = flyer.Pitch(ShotLaunch.Statcast(Speed.FromMetresPerSecond(v), 0, 0, 2000, 180), release, 0, 1.8);
            double a = air.Density * ball.CrossSectionalArea * 0.2 * v * v / (2 * ball.Mass), radius = v * v / a;
            double length = BaseballField.RubberToPlateMetres - BaseballField.PlateDepthMetres - release;
            double rise = radius - Math.Sqrt(radius * radius - length * length);
            Assert.That(p.InducedVerticalBreakInches, Is.EqualTo(rise / 0.0254).Within(1e-6));
            Assert.That(p.PlateHeightFeet, Is.EqualTo((1.8 + rise) / 0.3048).Within(1e-6));
            Assert.That(p.PlateSpeedMph, Is.EqualTo(v / 0.44704).Within(1e-6));
        }

        [Test]
        public void APitchThatLandsFirst_DoesNotCrossThePlate()
        {
            PitchResult p = Baseball().Pitch(ShotLaunch.Statcast(Speed.FromMilesPerHour(20), -5, 0, 0, 180), 1.8, 0, 1.8);
            Assert.That(p.CrossesPlate, Is.False);
            Assert.That(p.InducedVerticalBreakInches, Is.EqualTo(0));
        }
    }
}
