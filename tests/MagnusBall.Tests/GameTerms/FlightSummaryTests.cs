using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Presets;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.GameTerms
{
    /// <summary>
    /// The summary against closed forms in a vacuum, and the sports' judges against straight and parabolic flights whose
    /// crossings and landings are known exactly. RK4 integrates a parabola and a straight line exactly and the events are
    /// located on the step's cubic interpolant to 1e-12 s, so these hold to rounding: 1e-9 m and 1e-9 s.
    /// </summary>
    [TestFixture]
    public class FlightSummaryTests
    {
        private const double G = Gravity.Standard;

        private static ShotFlyer Vacuum(Ball ball, bool gravity = true) =>
            new ShotFlyer(FlightModel.Vacuum(ball, gravity ? Gravity.ZUp : Vector3d.Zero), ShotFrame.ZUp);

        [Test]
        public void VacuumFlight_MatchesTheParabola()
        {
            double v = 20, theta = 40 * Math.PI / 180, phi = 10 * Math.PI / 180, r = Ball.Tennis.Radius;
            FlightSummary s = Vacuum(Ball.Tennis).Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(v), 40, 10), 0, 0, r);
            double time = 2 * v * Math.Sin(theta) / G, carry = v * Math.Cos(theta) * time;
            Assert.Multiple(() =>
            {
                Assert.That(s.Landed, Is.True);
                Assert.That(s.FlightTimeSeconds, Is.EqualTo(time).Within(1e-9));
                Assert.That(s.CarryMetres, Is.EqualTo(carry).Within(1e-9));
                Assert.That(s.CarryYards, Is.EqualTo(carry / 0.9144).Within(1e-9));
                Assert.That(s.ApexMetres, Is.EqualTo(r + Math.Pow(v * Math.Sin(theta), 2) / (2 * G)).Within(1e-9));
                Assert.That(s.ApexFeet, Is.EqualTo(s.ApexMetres / 0.3048).Within(1e-12));
                Assert.That(s.LandingAngleDegrees, Is.EqualTo(40).Within(1e-7));
                Assert.That(s.LandingSpeedMetresPerSecond, Is.EqualTo(v).Within(1e-9));
                Assert.That(s.SideMetres, Is.EqualTo(carry * Math.Sin(phi)).Within(1e-9));
                Assert.That(s.SideYards, Is.EqualTo(s.SideMetres / 0.9144).Within(1e-12));
                Assert.That(s.CurveMetres, Is.EqualTo(0).Within(1e-9), "a vacuum flight does not curve");
            });
        }

        [Test]
        public void TryCross_GivesTheParabolasHeight()
        {
            double v = 20, theta = 30 * Math.PI / 180, h = 1;
            FlightSummary s = Vacuum(Ball.Tennis).Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(v), 30), 0, 0, h);
            Assert.That(s.TryCross(11.885, out double up, out double right), Is.True);
            double c = v * Math.Cos(theta);
            Assert.That(up, Is.EqualTo(h + 11.885 * Math.Tan(theta) - G * 11.885 * 11.885 / (2 * c * c)).Within(1e-9));
            Assert.That(right, Is.EqualTo(0).Within(1e-12));
            Assert.That(s.TryCross(500, out _, out _), Is.False, "it lands first");
        }

        [Test]
        public void NotLanding_IsSaid_AndNothingIsNaN()
        {
            FlightSummary s = Vacuum(Ball.Tennis, gravity: false).Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(1), 0), 0, 0, 1);
            Assert.That(s.Landed, Is.False);
            Assert.That(s.FlightTimeSeconds, Is.EqualTo(20).Within(1e-9), "the flight's time limit");
            Assert.That(double.IsFinite(s.CarryMetres + s.ApexMetres + s.LandingAngleDegrees + s.CurveMetres), Is.True);
        }

        // Tennis, table: launched level from a height, in a vacuum, landing at a chosen distance and side.
        private static FlightSummary LevelShot(Ball ball, double height, double distance, double directionDegrees = 0)
        {
            double fallTime = Math.Sqrt(2 * (height - ball.Radius) / G);
            return Vacuum(ball).Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(distance / fallTime), 0, directionDegrees), 0, 0, height);
        }

        private static FlightSummary Straight(Ball ball, double right, double up, double directionDegrees = 0) =>
            Vacuum(ball, gravity: false).Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(10), 0, directionDegrees), 0, right, up);

        [Test]
        public void Tennis_InOutWideShort_ByTheLandingPoint()
        {
            Ball ball = Ball.Tennis;
            double wide = Math.Atan(4.2 / 20) * 180 / Math.PI; // lands 4.2 m right of the centre line: outside 4.115, inside 5.485
            Assert.Multiple(() =>
            {
                Assert.That(TennisCourt.Judge(LevelShot(ball, 3, 20)), Is.EqualTo(ShotOutcome.In));
                Assert.That(TennisCourt.Judge(LevelShot(ball, 3, 23.7)), Is.EqualTo(ShotOutcome.In), "on the baseline");
                Assert.That(TennisCourt.Judge(LevelShot(ball, 3, 23.9)), Is.EqualTo(ShotOutcome.Out));
                Assert.That(TennisCourt.Judge(LevelShot(ball, 3, 20.44, wide)), Is.EqualTo(ShotOutcome.Wide));
                Assert.That(TennisCourt.Judge(LevelShot(ball, 3, 20.44, wide), doubles: true), Is.EqualTo(ShotOutcome.In));
                Assert.That(TennisCourt.Judge(LevelShot(ball, 3, 10)), Is.EqualTo(ShotOutcome.Short));
            });
        }

        [Test]
        public void Tennis_Net_WhenTheBallPassesLowerThanARadiusAboveTheNet()
        {
            Ball ball = Ball.Tennis;
            double top = TennisCourt.NetHeightAtCentreMetres + ball.Radius;
            // At 5 m right the net is 0.914 + 0.156 x 5 / 6.399 m high (straight from the centre strap to the posts).
            double atFive = TennisCourt.NetHeightAtCentreMetres + (TennisCourt.NetHeightAtPostsMetres - TennisCourt.NetHeightAtCentreMetres) * 5 / 6.399 + ball.Radius;
            Assert.Multiple(() =>
            {
                Assert.That(TennisCourt.Judge(Straight(ball, 0, top - 1e-3)), Is.EqualTo(ShotOutcome.Net));
                Assert.That(TennisCourt.Judge(Straight(ball, 0, top + 1e-3)), Is.EqualTo(ShotOutcome.Out), "clears the net and never lands");
                Assert.That(TennisCourt.Judge(Straight(ball, 5, atFive - 1e-3)), Is.EqualTo(ShotOutcome.Net));
                Assert.That(TennisCourt.Judge(Straight(ball, 5, atFive + 1e-3)), Is.EqualTo(ShotOutcome.Out));
                Assert.That(TennisCourt.Judge(Straight(ball, 7, 0.5)), Is.EqualTo(ShotOutcome.Out), "outside the posts the net is not in the way");
            });
        }

        [Test]
        public void TableTennis_NetInOut()
        {
            var ball = new Ball(0.0027, 0.020, Ball.ThinShellInertiaFactor);
            Assert.Multiple(() =>
            {
                Assert.That(TableTennisTable.Judge(LevelShot(ball, 0.4, 2.0)), Is.EqualTo(ShotOutcome.In));
                Assert.That(TableTennisTable.Judge(LevelShot(ball, 0.4, 2.8)), Is.EqualTo(ShotOutcome.Out));
                Assert.That(TableTennisTable.Judge(LevelShot(ball, 0.4, 1.0)), Is.EqualTo(ShotOutcome.Short));
                Assert.That(TableTennisTable.Judge(LevelShot(ball, 0.4, 2.0, 25)), Is.EqualTo(ShotOutcome.Wide), "0.93 m right of the centre line, outside 0.7625");
                Assert.That(TableTennisTable.Judge(Straight(ball, 0, TableTennisTable.NetHeightMetres + ball.Radius - 1e-3)), Is.EqualTo(ShotOutcome.Net));
            });
        }

        [Test]
        public void Soccer_InWideOverWoodworkShort_AtTheGoalLine()
        {
            Ball ball = SportPresets.Soccer.Ball;
            double r = ball.Radius, half = SoccerGoal.WidthMetres / 2, post = SoccerGoal.PostWidthMetres;
            Assert.Multiple(() =>
            {
                Assert.That(SoccerGoal.Judge(Straight(ball, 0, 1), 20), Is.EqualTo(ShotOutcome.In));
                Assert.That(SoccerGoal.Judge(Straight(ball, half - r - 1e-3, 1), 20), Is.EqualTo(ShotOutcome.In), "just inside the post");
                Assert.That(SoccerGoal.Judge(Straight(ball, half - r + 1e-3, 1), 20), Is.EqualTo(ShotOutcome.Woodwork));
                Assert.That(SoccerGoal.Judge(Straight(ball, half + post + r + 1e-3, 1), 20), Is.EqualTo(ShotOutcome.Wide));
                Assert.That(SoccerGoal.Judge(Straight(ball, 0, SoccerGoal.HeightMetres - r - 1e-3), 20), Is.EqualTo(ShotOutcome.In));
                Assert.That(SoccerGoal.Judge(Straight(ball, 0, SoccerGoal.HeightMetres), 20), Is.EqualTo(ShotOutcome.Woodwork), "the crossbar");
                Assert.That(SoccerGoal.Judge(Straight(ball, 0, SoccerGoal.HeightMetres + post + r + 1e-3), 20), Is.EqualTo(ShotOutcome.Over));
                Assert.That(SoccerGoal.Judge(Straight(ball, 5, 1), 20, goalCentreRightMetres: 5), Is.EqualTo(ShotOutcome.In), "a goal off the forward axis");
                Assert.That(SoccerGoal.Judge(Straight(ball, 0, 1, directionDegrees: 180), 20), Is.EqualTo(ShotOutcome.Short), "never reaches the line");
            });
        }

        [Test]
        public void TheTopspinForehand_ClearsTheNetAndLandsIn_OrHitsTheNetWhenHitFlat()
        {
            // The docs' forehand (docs/shots.md): 120 km/h, 8 degrees, 2500 rpm topspin from 1 m, half a metre behind the
            // baseline. At 5 degrees the same shot passes the net at 0.73 m, into it.
            var court = new ShotFlyer(SportPresets.Tennis.CreateModel(Air.AtAltitude(0), Gravity.ZUp), ShotFrame.ZUp);
            FlightSummary good = court.Fly(ShotLaunch.ByEffect(Speed.FromKilometresPerHour(120), 8, topspinRpm: 2500), -0.5, 0, 1);
            FlightSummary low = court.Fly(ShotLaunch.ByEffect(Speed.FromKilometresPerHour(120), 5, topspinRpm: 2500), -0.5, 0, 1);
            Assert.That(TennisCourt.Judge(good), Is.EqualTo(ShotOutcome.In));
            Assert.That(TennisCourt.Judge(low), Is.EqualTo(ShotOutcome.Net));
        }

        [Test]
        public void AShotAtTheSpeedOfLight_IsRefused_NotReportedAsALanding()
        {
            // RK4 (substepped) cannot fly a 2.7 g ball at 3e8 m/s: the flight diverges, and a landing of it would be a wrong answer.
            var flyer = new ShotFlyer(SportPresets.TableTennis.CreateModel(Air.AtAltitude(0), Gravity.ZUp), ShotFrame.ZUp);
            var e = Assert.Throws<ArgumentException>(() => flyer.Fly(ShotLaunch.ByEffect(Speed.FromMetresPerSecond(3e8), 10), 0, 0, 1));
            Assert.That(e!.ParamName, Is.EqualTo("launch"));
        }

        [Test]
        public void Judges_RefuseNull()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => TennisCourt.Judge(null!))!.ParamName, Is.EqualTo("flight"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => SoccerGoal.Judge(null!, 20))!.ParamName, Is.EqualTo("flight"));
            FlightSummary s = Straight(Ball.Tennis, 0, 1);
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => SoccerGoal.Judge(s, double.NaN))!.ParamName, Is.EqualTo("goalLineForwardMetres"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.TryCross(double.PositiveInfinity, out _, out _))!.ParamName, Is.EqualTo("forwardMetres"));
        }
    }
}
