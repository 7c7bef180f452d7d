using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Swings;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// The inverses of the swing helpers (<see cref="SwingAim"/>): for a racket, a club, a bat and a kick, a target made
    /// by flying a known swing is reached again from a swing started several degrees off, and the solved swing's launch,
    /// flown independently of the aim solver (<see cref="TrajectoryPredictor"/>), lands on it.
    /// </summary>
    [TestFixture]
    public class SwingAimTests
    {
        private const double Mph = 0.44704;

        // The inverse accepts an aim solution only within SwingAim.MissTolerance (1e-4 m) of the target, and the solved
        // launch direction agrees with it to 1e-9 rad (1e-6 m over 250 m): the landing must be within the miss tolerance.
        private const double LandingTolerance = SwingAim.MissTolerance;

        private static readonly LaunchFrame ZUp = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);
        private static readonly LaunchFrame UnityYUp = new LaunchFrame(Vector3d.UnitY, Vector3d.UnitZ);

        private sealed class Sport
        {
            public Sport(SportPreset preset, Vector3d gravity, double step)
            {
                Ball = preset.Ball;
                Model = preset.CreateModel(Air.SeaLevel, gravity);
                Step = step;
                Aim = new SwingAim(new AimSolver(Model, RungeKutta4.Instance, step, Plane.Ground(Model), maximumFlightTime: 20), Ball);
                Predictor = new TrajectoryPredictor(Model, RungeKutta4.Instance, step, FlightEventSet.ForModel(Model));
            }

            public Ball Ball { get; }

            public FlightModel Model { get; }

            public double Step { get; }

            public SwingAim Aim { get; }

            public TrajectoryPredictor Predictor { get; }

            /// <summary>Where a launch first comes down to the ground (the plane through the origin normal to up).</summary>
            public Vector3d Landing(in Vector3d position, in SwingLaunch launch)
            {
                Prediction p = Predictor.Predict(launch.LaunchState(position), 20, Span<Vector3d>.Empty);
                Assert.That(p.Stopped, Is.True, "the launch lands");
                return p.EndState.Position;
            }
        }

        // RK4 at 1/240 s for tennis and soccer, 1/120 s for the long golf and baseball flights (the same step for the target, the solve and the check).
        private static readonly Sport Tennis = new Sport(SportPresets.Tennis, Gravity.ZUp, 1.0 / 240);
        private static readonly Sport Golf = new Sport(SportPresets.Golf, Gravity.ZUp, 1.0 / 120);
        private static readonly Sport Baseball = new Sport(SportPresets.Baseball, Gravity.ZUp, 1.0 / 120);
        private static readonly Sport Soccer = new Sport(SportPresets.Soccer, Gravity.YUp, 1.0 / 240);

        private static void AssertLands(Sport sport, in Vector3d position, in SwingLaunch launch, in Vector3d target, string what)
        {
            double miss = Vector3d.Distance(sport.Landing(position, launch), target);
            TestContext.Out.WriteLine($"{what}: lands {miss:E2} m from the target");
            Assert.That(miss, Is.LessThan(LandingTolerance), what);
        }

        [Test]
        public void Racket_FindsTheFaceAndAzimuth_ThatLandOnTheTarget()
        {
            var position = new Vector3d(0, 0, 1);
            var incoming = new Vector3d(-14, 0.5, -1);
            var known = new RacketSwing(26, 40, 1.5, azimuthDegrees: 4);
            Vector3d target = Tennis.Landing(position, known.Hit(Tennis.Ball, ZUp, position, incoming, Vector3d.Zero));
            SwingSolution<RacketSwing> s = Tennis.Aim.RacketFaceToReach(known.WithFace(4.5, 0), ZUp, position, incoming, Vector3d.Zero, target);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Iterations, Is.LessThanOrEqualTo(SwingAim.MaximumIterations));
            Assert.That(s.Swing.Speed, Is.EqualTo(known.Speed));
            Assert.That(s.Swing.PathElevationDegrees, Is.EqualTo(known.PathElevationDegrees));
            TestContext.Out.WriteLine($"racket: {s.Swing}, {s.Iterations} iterations; target {target}");
            AssertLands(Tennis, position, s.Swing.Hit(Tennis.Ball, ZUp, position, incoming, Vector3d.Zero), target, "racket");
        }

        [Test]
        public void Racket_AimedAtACourtPoint_WithTheGroundAtTheBallsCentre_LandsOverIt()
        {
            // The tennis scene's ground is the plane of the ball's centre, one radius up; a game gives a point on the court.
            // The aim solver answers such a below-ground target with the launch that comes down over it (Miss: the radius),
            // and the inverse judges that landing along the ground, so it solves (it came back Unreachable: Miss 0.033 m is
            // over its 1e-4 m).
            double r = Tennis.Ball.Radius;
            Plane ground = Plane.Ground(Tennis.Model, new Vector3d(0, 0, r));
            var aim = new SwingAim(new AimSolver(Tennis.Model, RungeKutta4.Instance, Tennis.Step, ground, maximumFlightTime: 20), Tennis.Ball);
            var position = new Vector3d(0, 0, 1);
            var incoming = new Vector3d(-14, 0.5, -1);
            var courtPoint = new Vector3d(21, 1.5, 0);
            SwingSolution<RacketSwing> s = aim.RacketFaceToReach(new RacketSwing(26, 40, 4.5), ZUp, position, incoming, Vector3d.Zero, courtPoint);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Aim.Miss, Is.EqualTo(r).Within(1e-4), "the aim solver's miss is the depth below its landing");

            // Flown independently (RK4, the same step) to the ground at the ball's centre: down over the court point.
            var predictor = new TrajectoryPredictor(Tennis.Model, RungeKutta4.Instance, Tennis.Step, new FlightEventSet(Tennis.Model.Up, ground));
            Prediction p = predictor.Predict(s.Launch.LaunchState(position), 20, Span<Vector3d>.Empty);
            Assert.That(p.Stopped, Is.True);
            Vector3d landing = p.EndState.Position;
            Assert.That(landing.Z, Is.EqualTo(r).Within(1e-9), "on the ground plane");
            Assert.That(Math.Sqrt((landing.X - courtPoint.X) * (landing.X - courtPoint.X) + (landing.Y - courtPoint.Y) * (landing.Y - courtPoint.Y)),
                Is.LessThan(LandingTolerance), "over the court point");
        }

        [Test]
        public void Club_FindsTheLoftAndFace_ThatCarryToTheTarget_KeepingSpeedAttackAndFaceToPath()
        {
            // A 7-iron-like delivery with a 2 deg fade (face 2 deg open to the path): the inverse keeps the curve.
            var position = new Vector3d(0, 0, Golf.Ball.Radius);
            var known = new ClubSwing(90 * Mph, 24, -4.3, faceAngleDegrees: 1, clubPathDegrees: -1, headMass: 0.268, restitution: 0.765);
            Vector3d target = Golf.Landing(position, known.Hit(Golf.Ball, ZUp, position));
            var start = new ClubSwing(90 * Mph, 20, -4.3, faceAngleDegrees: 4, clubPathDegrees: 2, headMass: 0.268, restitution: 0.765);
            SwingSolution<ClubSwing> s = Golf.Aim.ClubFaceToReach(start, ZUp, position, target);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Swing.Speed, Is.EqualTo(start.Speed));
            Assert.That(s.Swing.AttackAngleDegrees, Is.EqualTo(start.AttackAngleDegrees));
            Assert.That(s.Swing.ClubPathDegrees - s.Swing.FaceAngleDegrees, Is.EqualTo(-2).Within(1e-12));
            TestContext.Out.WriteLine($"club: {s.Swing}, {s.Iterations} iterations; target {target}");
            AssertLands(Golf, position, s.Swing.Hit(Golf.Ball, ZUp, position), target, "club");
        }

        [Test]
        public void Club_WithARigidHead_KeepsTheHead_AndLandsOnTheTarget()
        {
            // The measured driver head rotating about its CG (ClubHead.MeasuredDriver): the inverse solves loft and face
            // with that head (not a point mass of its mass) and the solved swing lands on the target.
            var position = new Vector3d(0, 0, Golf.Ball.Radius);
            var known = new ClubSwing(105 * Mph, 12, -1, 1, -0.5, ClubHead.MeasuredDriver);
            Vector3d target = Golf.Landing(position, known.Hit(Golf.Ball, ZUp, position));
            var start = new ClubSwing(105 * Mph, 15, -1, 3, 1.5, ClubHead.MeasuredDriver);
            SwingSolution<ClubSwing> s = Golf.Aim.ClubFaceToReach(start, ZUp, position, target);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Swing.Head.IsPointMass, Is.False);
            Assert.That(s.Swing.Head.CenterOfGravityDepth, Is.EqualTo(ClubHead.MeasuredDriver.CenterOfGravityDepth));
            Assert.That(s.Swing.Head.HeelToeInertia, Is.EqualTo(ClubHead.MeasuredDriver.HeelToeInertia));
            TestContext.Out.WriteLine($"rigid club: {s.Swing}, {s.Iterations} iterations; target {target}");
            AssertLands(Golf, position, s.Swing.Hit(Golf.Ball, ZUp, position), target, "rigid club");
        }

        [Test]
        public void Bat_FindsThePathElevationAndAzimuth_ThatLandOnTheTarget_KeepingTheUndercut()
        {
            var position = new Vector3d(0, 0, 1);
            var pitch = new Vector3d(-90 * Mph, 0, -1.5);
            var known = new BatSwing(75 * Mph, 0.015, 8, -4);
            Vector3d target = Baseball.Landing(position, known.Hit(Baseball.Ball, ZUp, position, pitch, Vector3d.Zero));
            SwingSolution<BatSwing> s = Baseball.Aim.BatPathToReach(new BatSwing(75 * Mph, 0.015, 2, 2), ZUp, position, pitch, Vector3d.Zero, target);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Swing.Undercut, Is.EqualTo(0.015));
            TestContext.Out.WriteLine($"bat: {s.Swing}, {s.Iterations} iterations; target {target}");
            AssertLands(Baseball, position, s.Swing.Hit(Baseball.Ball, ZUp, position, pitch, Vector3d.Zero), target, "bat");
        }

        [Test]
        public void Kick_FindsTheFootPath_ThatLandsOnTheTarget_InUnitysYUpFrame_KeepingTheCurl()
        {
            var position = new Vector3d(0, Soccer.Ball.Radius, 0);
            var known = new KickSwing(24, 0.06, 0.5, elevationDegrees: 18, azimuthDegrees: -5);
            Vector3d target = Soccer.Landing(position, known.Hit(Soccer.Ball, UnityYUp, position));
            SwingSolution<KickSwing> s = Soccer.Aim.KickToReach(new KickSwing(24, 0.06, 0.5, elevationDegrees: 12, azimuthDegrees: 3), UnityYUp, position, target);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Swing.Offset, Is.EqualTo(0.06));
            Assert.That(Math.Abs(s.Launch.LaunchSpin.Sidespin), Is.GreaterThan(10), "the kick still curls");
            TestContext.Out.WriteLine($"kick: {s.Swing}, {s.Iterations} iterations; target {target}");
            AssertLands(Soccer, position, s.Swing.Hit(Soccer.Ball, UnityYUp, position), target, "kick");
        }

        [Test]
        public void Kick_AtAPointInTheGoalMouth_PassesThroughIt()
        {
            // A target off the ground: a free kick 20 m out, 2 m up and 3 m to the side. The aim solver's target plane
            // passes through the target across the direction to it; the solved launch crosses it there.
            var position = new Vector3d(0, Soccer.Ball.Radius, 0);
            var target = new Vector3d(3, 2, 20);
            SwingSolution<KickSwing> s = Soccer.Aim.KickToReach(new KickSwing(25, 0.05, 0.5, elevationDegrees: 15), UnityYUp, position, target);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Aim.Miss, Is.LessThan(SwingAim.MissTolerance));
            var toTarget = new Vector3d(target.X - position.X, 0, target.Z - position.Z);
            var plane = new Plane(target, toTarget);
            var predictor = new TrajectoryPredictor(Soccer.Model, RungeKutta4.Instance, Soccer.Step, FlightEventSet.ForModel(Soccer.Model, plane));
            Prediction p = predictor.Predict(s.Launch.LaunchState(position), 5, Span<Vector3d>.Empty, FlightEventKinds.PlaneCrossing);
            Assert.That(p.Stopped, Is.True);
            double miss = Vector3d.Distance(p.EndState.Position, target);
            TestContext.Out.WriteLine($"kick into the goal mouth: {s.Swing}, passes {miss:E2} m from the target");
            Assert.That(miss, Is.LessThan(LandingTolerance));
        }

        [Test]
        public void ReadmeSwingAimExample_Runs()
        {
            // README's "From a swing to a launch" inverse example, compiled and run, then checked like the goal-mouth test.
            var soccer = SportPresets.Soccer;
            FlightModel model = soccer.CreateModel(Air.SeaLevel, Gravity.YUp);
            var aim = new SwingAim(new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, Plane.Ground(model)), soccer.Ball);
            var curler = new KickSwing(speed: 25, offset: 0.05, friction: 0.5);
            var frameYUp = new LaunchFrame(Vector3d.UnitY, Vector3d.UnitZ);
            SwingSolution<KickSwing> kick = aim.KickToReach(curler, frameYUp, new Vector3d(0, soccer.Ball.Radius, 0), target: new Vector3d(3, 2, 20));
            TestContext.Out.WriteLine($"README: {kick}");
            Assert.That(kick.IsSolved, Is.True);
            Assert.That(kick.Aim.Miss, Is.LessThan(SwingAim.MissTolerance));
            Assert.That(Math.Abs(kick.Launch.LaunchSpin.Sidespin), Is.GreaterThan(10), "it curls");
        }

        [Test]
        public void ATargetOutOfReach_IsUnreachable_NotAnException()
        {
            var position = new Vector3d(0, Soccer.Ball.Radius, 0);
            SwingSolution<KickSwing> far = Soccer.Aim.KickToReach(new KickSwing(10, 0.02), UnityYUp, position, new Vector3d(0, 0, 300));
            Assert.That(far.Status, Is.EqualTo(AimStatus.Unreachable));
            var golfPosition = new Vector3d(0, 0, Golf.Ball.Radius);
            SwingSolution<ClubSwing> tooFar = Golf.Aim.ClubFaceToReach(new ClubSwing(20, 20, -4), ZUp, golfPosition, new Vector3d(400, 0, 0));
            Assert.That(tooFar.Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(tooFar.Iterations, Is.LessThanOrEqualTo(SwingAim.MaximumIterations));
        }

        [Test]
        public void TargetsNear1e308Away_AreUnreachable_NotAFalseStraightAboveError()
        {
            // The launch at x = +1e308, the target at x = -1e308: their difference overflows. The swing inverse takes the
            // aim solver's own target frame (formed from quarters there), so this finite input gives Unreachable, as
            // AimSolver.AnglesToReach does on the same points, not "straight above or below" (the plain difference's NaN).
            var position = new Vector3d(1e308, 0, 1);
            var target = new Vector3d(-1e308, 0, 0);
            SwingSolution<RacketSwing> racket = Tennis.Aim.RacketFaceToReach(
                new RacketSwing(30, 10, 5), ZUp, position, new Vector3d(15, 0, -2), Vector3d.Zero, target);
            Assert.That(racket.Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(Tennis.Aim.Solver.AnglesToReach(position, 30, LaunchSpin.None, target).Status, Is.EqualTo(AimStatus.Unreachable));
            SwingSolution<ClubSwing> club = Golf.Aim.ClubFaceToReach(new ClubSwing(50, 20, 0), ZUp, position, target);
            Assert.That(club.Status, Is.EqualTo(AimStatus.Unreachable));

            // The same threshold as the aim solver: a target 1e-7 m beside straight above is refused by both (it used to
            // pass the inverse's own 1e-9 m check and then fail inside the aim solver).
            var p = new Vector3d(0, 0, 1);
            var nearlyAbove = new Vector3d(1e-7, 0, 30);
            Assert.Throws<ArgumentException>(() => Golf.Aim.ClubFaceToReach(new ClubSwing(50, 20, 0), ZUp, p, nearlyAbove));
            Assert.Throws<ArgumentException>(() => Golf.Aim.Solver.AnglesToReach(p, 50, LaunchSpin.None, nearlyAbove));
        }

        [Test]
        public void BadInput_IsRefused_NamingTheParameter()
        {
            void Check(string name, TestDelegate action)
            {
                var e = (ArgumentException)Assert.Throws(Is.InstanceOf<ArgumentException>(), action)!;
                Assert.That(e.ParamName, Is.EqualTo(name));
                Assert.That(e.Message, Does.Contain(name));
            }

            var p = new Vector3d(0, 0, 1);
            var t = new Vector3d(20, 0, 0);
            SwingAim golf = Golf.Aim, baseball = Baseball.Aim, tennis = Tennis.Aim;
            Check("solver", () => new SwingAim(null!, Ball.Tennis));
            Check("ball", () => new SwingAim(golf.Solver, null!));
            Check("ball", () => new SwingAim(Soccer.Aim.Solver, Ball.Tennis)); // a tennis ball hit, flown as a soccer ball
            Check("solver", () => new SwingAim(null!));
            Assert.That(new SwingAim(Soccer.Aim.Solver).Ball, Is.SameAs(Soccer.Aim.Solver.Model.Ball), "the one-argument form hits the model's ball");
            Check("swing", () => golf.ClubFaceToReach(default, ZUp, p, t));
            Check("swing", () => baseball.BatPathToReach(default, ZUp, p, new Vector3d(-40, 0, 0), Vector3d.Zero, t));
            Check("kick", () => Soccer.Aim.KickToReach(default, UnityYUp, p, t));
            Check("swing", () => tennis.RacketFaceToReach(default, ZUp, p, Vector3d.Zero, Vector3d.Zero, t));
            Check("frame", () => golf.ClubFaceToReach(new ClubSwing(50, 20, 0), default, p, t));
            Check("position", () => golf.ClubFaceToReach(new ClubSwing(50, 20, 0), ZUp, new Vector3d(double.NaN, 0, 0), t));
            Check("target", () => golf.ClubFaceToReach(new ClubSwing(50, 20, 0), ZUp, p, new Vector3d(0, 0, 30)));
            Check("target", () => golf.ClubFaceToReach(new ClubSwing(50, 20, 0), ZUp, p, new Vector3d(double.PositiveInfinity, 0, 0)));
            Check("maximumAzimuthDegrees", () => golf.ClubFaceToReach(new ClubSwing(50, 20, 0), ZUp, p, t, 90));
            Check("pitchVelocity", () => baseball.BatPathToReach(new BatSwing(30), ZUp, p, new Vector3d(double.NaN, 0, 0), Vector3d.Zero, t));
            Check("pitchSpin", () => baseball.BatPathToReach(new BatSwing(30), ZUp, p, new Vector3d(-40, 0, 0), new Vector3d(0, double.NaN, 0), t));
            Check("incomingVelocity", () => tennis.RacketFaceToReach(new RacketSwing(20, 10, 0), ZUp, p, new Vector3d(0, double.NaN, 0), Vector3d.Zero, t));
            Check("incomingSpin", () => tennis.RacketFaceToReach(new RacketSwing(20, 10, 0), ZUp, p, Vector3d.Zero, new Vector3d(0, double.NaN, 0), t));
            // Geometry that depends on the ball: the swing helper's own check, named by the ball.
            Check("ball", () => Soccer.Aim.KickToReach(new KickSwing(25, 0.2), UnityYUp, new Vector3d(0, 0.11, 0), t));
        }
    }
}
