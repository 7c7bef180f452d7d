using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Swings;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// The impact law at the edges of finite input (found by a review's probes): speeds near double.MaxValue, relative
    /// velocities that overflow, bodies far lighter than the ball, and swings that are the default value. The rules: no NaN
    /// for finite valid input, bad input refused naming the parameter.
    /// </summary>
    [TestFixture]
    public class ImpactExtremesTests
    {
        private const double TwoTo520 = 3.432398830065305e156; // 2^520, past the law's 2^500 switch to its scaled path
        private static readonly LaunchFrame ZUp = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);

        private static void AssertNoNaN(ImpactOutcome o, string what)
        {
            Assert.Multiple(() =>
            {
                Assert.That(IsNaN(o.Velocity), Is.False, $"{what}: velocity {o.Velocity}");
                Assert.That(IsNaN(o.AngularVelocity), Is.False, $"{what}: spin {o.AngularVelocity}");
                Assert.That(IsNaN(o.Impulse), Is.False, $"{what}: impulse {o.Impulse}");
            });
        }

        private static bool IsNaN(in Vector3d v) => double.IsNaN(v.X) || double.IsNaN(v.Y) || double.IsNaN(v.Z);

        [TestCase(0.0, 0.0)]
        [TestCase(0.002, 0.0)]
        [TestCase(0.002, 0.4)]
        public void BeyondTwoTo500MetresPerSecond_TheLawIsItsOwnScaledCopy_BitForBit(double forceOffset, double tangentialRestitution)
        {
            // Above 2^500 m/s the law is solved at 2^-600 of the velocities and scaled back. With the offset fixed (D1 = 0)
            // the law is linear in the velocities and powers of two scale exactly, so an impact 2^520 times faster is the
            // moderate one times 2^520 in every bit: the scaled path is the same law, not an approximation of it.
            var contact = new ContactProperties(0.8, 0.5, tangentialRestitution, forceOffset);
            var normal = new Vector3d(0.2, 0, 1); // both bodies normalise the same vector
            var body = ImpactBody.Moving(new Vector3d(-3, 1, 2), normal, 0.3);
            var v = new Vector3d(12, -4, -20);
            var w = new Vector3d(150, -80, 40);
            ImpactOutcome moderate = Impact.Resolve(Ball.Tennis, Vector3d.Zero, v, w, body, contact);
            var fastBody = ImpactBody.Moving(body.Velocity * TwoTo520, normal, 0.3);
            ImpactOutcome fast = Impact.Resolve(Ball.Tennis, Vector3d.Zero, v * TwoTo520, w * TwoTo520, fastBody, contact);
            Assert.That(moderate.Regime, Is.Not.EqualTo(BounceRegime.None));
            Assert.That(fast.Regime, Is.EqualTo(moderate.Regime));
            Assert.That(fast.Velocity, Is.EqualTo(moderate.Velocity * TwoTo520));
            Assert.That(fast.AngularVelocity, Is.EqualTo(moderate.AngularVelocity * TwoTo520));
            Assert.That(fast.Impulse, Is.EqualTo(moderate.Impulse * TwoTo520));
            Assert.That(fast.NormalRestitution, Is.EqualTo(moderate.NormalRestitution));

            // A rotating body (its surface velocity from the spin about a point off the contact) scales the same way.
            var spinning = new ImpactBody(new Vector3d(0.1, -0.05, -0.2), new Vector3d(-3, 1, 2), new Vector3d(20, -10, 35), normal, 0.3);
            var fastSpinning = new ImpactBody(spinning.Point, spinning.Velocity * TwoTo520, spinning.AngularVelocity * TwoTo520, normal, 0.3);
            ImpactOutcome turned = Impact.Resolve(Ball.Tennis, Vector3d.Zero, v, w, spinning, contact);
            ImpactOutcome fastTurned = Impact.Resolve(Ball.Tennis, Vector3d.Zero, v * TwoTo520, w * TwoTo520, fastSpinning, contact);
            Assert.That(fastTurned.Regime, Is.EqualTo(turned.Regime));
            Assert.That(fastTurned.Velocity, Is.EqualTo(turned.Velocity * TwoTo520));
            Assert.That(fastTurned.AngularVelocity, Is.EqualTo(turned.AngularVelocity * TwoTo520));
            Assert.That(fastTurned.Impulse, Is.EqualTo(turned.Impulse * TwoTo520));

            // The rigid club head's law (no offset; the measured driver head, turning about its CG) too.
            var golfBall = new Ball(0.04593, 0.02135);
            SwingLaunch drive = new ClubSwing(50, 12, -1, 2, -1, ClubHead.MeasuredDriver).Hit(golfBall, ZUp, Vector3d.Zero);
            SwingLaunch fastDrive = new ClubSwing(50 * TwoTo520, 12, -1, 2, -1, ClubHead.MeasuredDriver).Hit(golfBall, ZUp, Vector3d.Zero);
            Assert.That(fastDrive.Impact.Regime, Is.EqualTo(drive.Impact.Regime));
            Assert.That(fastDrive.Velocity, Is.EqualTo(drive.Velocity * TwoTo520));
            Assert.That(fastDrive.AngularVelocity, Is.EqualTo(drive.AngularVelocity * TwoTo520));

            // The ground bounce (CrossBounce) takes the same path (on a surface whose offset does not grow with speed; the
            // built-in courts' does, so there the scaled law is a different bounce, as the law says).
            var court = new CrossBounce(new Surface("fixed offset", 0.8, 0, 0.5, tangentialRestitution, forceOffset, 0));
            BounceOutcome ground = court.Bounce(Ball.Tennis, Vector3d.UnitZ, v, w);
            BounceOutcome fastGround = court.Bounce(Ball.Tennis, Vector3d.UnitZ, v * TwoTo520, w * TwoTo520);
            Assert.That(fastGround.Regime, Is.EqualTo(ground.Regime));
            Assert.That(fastGround.Velocity, Is.EqualTo(ground.Velocity * TwoTo520));
            Assert.That(fastGround.AngularVelocity, Is.EqualTo(ground.AngularVelocity * TwoTo520));
        }

        [Test]
        public void SpeedsNearTheLargestDouble_GiveNoNaN()
        {
            // Each of these gave NaN before: (1 + e) vn or alpha' R w overflowed and met as infinity minus infinity.
            BounceOutcome bounce = CrossBounce.Hard.Bounce(Ball.Tennis, Vector3d.UnitZ, new Vector3d(1.7e308, 0, -1.7e308), Vector3d.Zero);
            Assert.That(IsNaN(bounce.Velocity) || IsNaN(bounce.AngularVelocity), Is.False, bounce.ToString());
            Assert.That(bounce.Velocity.Z, Is.GreaterThan(0), "it still bounces up");

            SwingLaunch racket = new RacketSwing(1e308, 10, 5).Hit(Ball.Tennis, ZUp, Vector3d.Zero, new Vector3d(-20, 0, 0), Vector3d.Zero);
            AssertNoNaN(racket.Impact, "racket at 1e308 m/s");

            // A bat and a pitch near the largest double, head on: their relative velocity overflows to infinity; the
            // friction too is near the largest double.
            SwingLaunch bat = new BatSwing(1.7e308, 0.05, 45, 90, 0.2, 0.5, 1.7e308).Hit(
                MagnusBall.Presets.SportPresets.Baseball.Ball, ZUp, Vector3d.Zero, new Vector3d(-1.7e308, 1.7e308, -1.7e308), new Vector3d(1.7e308, -1.7e308, 1.7e308));
            AssertNoNaN(bat.Impact, "bat near 1.7e308");

            SwingLaunch club = new ClubSwing(1e308, 10, 0, 0, 0, ClubHead.MeasuredDriver).Hit(new Ball(0.04593, 0.02135), ZUp, Vector3d.Zero);
            AssertNoNaN(club.Impact, "rigid club head at 1e308 m/s");

            // A tiny ball spinning near the largest double: |w| R is moderate, but n x w itself overflowed before R
            // multiplied it (NaN velocity and spin, before and after the first fix).
            var tiny = new Ball(0.057, 1e-160);
            ImpactOutcome spinning = Impact.Resolve(tiny, Vector3d.Zero, new Vector3d(3, 0, -10), new Vector3d(1.7e308, -1.7e308, 0),
                ImpactBody.Immovable(new Vector3d(1, 1, 1)), new ContactProperties(0.8, 0.5));
            AssertNoNaN(spinning, "a 1e-160 m ball at 1.7e308 rad/s");

            // The impulse of a ball at -1e308 m/s into a wall (e 0.8): 0.057 x 1.8 x 1e308 = 1.03e307 N s, finite (the scaled impulse is
            // multiplied by the mass before it is scaled back).
            ImpactOutcome wall = Impact.Resolve(Ball.Tennis, Vector3d.Zero, new Vector3d(0, 0, -1e308), Vector3d.Zero,
                ImpactBody.Immovable(Vector3d.UnitZ), new ContactProperties(0.8, 0.5));
            Assert.That(double.IsFinite(wall.Impulse.Z), Is.True, wall.Impulse.ToString());
            Assert.That(wall.Impulse.Z, Is.EqualTo(Ball.Tennis.Mass * 1.8 * 1e308).Within(1e-12 * 1.03e307));

            // A body spinning near 1e308 rad/s with a lever near 1e308 m: its surface velocity is beyond even the scaled
            // range, so no impact can be formed: refused, naming the body (it read as no impact before).
            var far = new ImpactBody(new Vector3d(-1e308, -1e308, 0), Vector3d.Zero, new Vector3d(1e308, -1e308, 1e308), Vector3d.UnitZ, 1);
            var refused = Assert.Throws<ArgumentException>(() => Impact.Resolve(
                Ball.Tennis, new Vector3d(1e308, 1e308, 0), Vector3d.Zero, Vector3d.Zero, far, new ContactProperties(0.8, 0.5)))!;
            Assert.That(refused.ParamName, Is.EqualTo("body"));
        }

        [Test]
        public void AnEnormousFriction_IsCappedWhereItWouldOverflow_AndAGrazingImpactStillGrips()
        {
            // The law caps friction at 1e290 ((1 + alpha') mu would overflow past it). A first cap at 1e100 turned this grazing
            // grip (normal speed 1e-200 m/s, friction 1e200) into a slide: the cap is now where it changes nothing below it.
            var contact = new ContactProperties(0.8, 1e200);
            BounceOutcome graze = new CrossBounce(new Surface("sticky", 0.8, 0, 1e200, 0, 0, 0)).Bounce(
                Ball.Tennis, Vector3d.UnitZ, new Vector3d(1, 0, -1e-200), Vector3d.Zero);
            Assert.That(graze.Regime, Is.EqualTo(BounceRegime.Grip));
            ImpactOutcome point = Impact.Resolve(Ball.Tennis, Vector3d.Zero, new Vector3d(1, 0, -1e-200), Vector3d.Zero,
                ImpactBody.Immovable(Vector3d.UnitZ), contact);
            Assert.That(point.Regime, Is.EqualTo(BounceRegime.Grip));
            ImpactOutcome huge = Impact.Resolve(Ball.Tennis, Vector3d.Zero, new Vector3d(5, 0, -10), Vector3d.Zero,
                ImpactBody.Immovable(Vector3d.UnitZ), new ContactProperties(0.8, double.MaxValue));
            AssertNoNaN(huge, "friction double.MaxValue");
            Assert.That(huge.Regime, Is.EqualTo(BounceRegime.Grip));
        }

        [Test]
        public void ABodyFarLighterThanTheBall_IsRefused_NamingIt()
        {
            // m/M overflowed (M = 1e-310 kg against a 57 g ball) and the law gave NaN. The law takes m/M up to 1e12; the
            // swings, whose body mass is their own parameter, take at least a milligram (as ClubHead always did).
            var contact = new ContactProperties(0.8, 0.5);
            var e = Assert.Throws<ArgumentException>(() => Impact.Resolve(
                Ball.Tennis, Vector3d.Zero, new Vector3d(5, 0, -10), Vector3d.Zero, ImpactBody.Moving(Vector3d.Zero, Vector3d.UnitZ, 1e-310), contact))!;
            Assert.That(e.ParamName, Is.EqualTo("body"));
            Assert.That(e.Message, Does.Contain("1E-12"));
            ImpactOutcome light = Impact.Resolve(
                Ball.Tennis, Vector3d.Zero, new Vector3d(5, 0, -10), Vector3d.Zero, ImpactBody.Moving(Vector3d.Zero, Vector3d.UnitZ, 0.06e-12), contact);
            AssertNoNaN(light, "m/M just under 1e12");
            Assert.That(light.Velocity.Z, Is.EqualTo(-10).Within(1e-9), "a body a trillion times lighter hardly changes the ball");

            var foot = Assert.Throws<ArgumentOutOfRangeException>(() => new KickSwing(25, 0.05, footMass: 1e-308))!;
            Assert.That(foot.ParamName, Is.EqualTo("footMass"));
            var head = Assert.Throws<ArgumentOutOfRangeException>(() => new ClubSwing(50, 10, 0, headMass: 1e-309))!;
            Assert.That(head.ParamName, Is.EqualTo("headMass"));
            Assert.That(new KickSwing(25, 0.05, footMass: 1e-6).FootMass, Is.EqualTo(1e-6), "a milligram is accepted");

            // A ball over 1e12 times the foot's or the head's mass: refused by the swing, naming its own parameter (the ball).
            var heavyBall = new Ball(1e7, 0.11);
            var kick = Assert.Throws<ArgumentException>(() => new KickSwing(25, 0.05, footMass: 1e-6).Hit(heavyBall, ZUp, Vector3d.Zero))!;
            Assert.That(kick.ParamName, Is.EqualTo("ball"));
            var drive = Assert.Throws<ArgumentException>(() => new ClubSwing(50, 10, 0, headMass: 1e-6).Hit(heavyBall, ZUp, Vector3d.Zero))!;
            Assert.That(drive.ParamName, Is.EqualTo("ball"));
        }

        [Test]
        public void DefaultSwings_AndADefaultFrame_AreRefused_ForWhatTheyAre()
        {
            // Before: ArgumentException naming "effectiveMass", a parameter of no method called, or (the frame) accepted and
            // failing later in a property getter.
            var ball = Ball.Tennis;
            Assert.Throws<InvalidOperationException>(() => default(KickSwing).Hit(Ball.Soccer, ZUp, Vector3d.Zero));
            Assert.Throws<InvalidOperationException>(() => default(ClubSwing).Hit(ball, ZUp, Vector3d.Zero));
            Assert.Throws<InvalidOperationException>(() => default(BatSwing).Hit(MagnusBall.Presets.SportPresets.Baseball.Ball, ZUp, Vector3d.Zero, new Vector3d(-40, 0, 0), Vector3d.Zero));
            Assert.Throws<InvalidOperationException>(() => default(RacketSwing).Hit(ball, ZUp, Vector3d.Zero, new Vector3d(-20, 0, 0), Vector3d.Zero));
            SwingLaunch hit = new RacketSwing(30, 10, 5).Hit(ball, ZUp, Vector3d.Zero, new Vector3d(-20, 0, 0), Vector3d.Zero);
            var frame = Assert.Throws<ArgumentException>(() => new SwingLaunch(hit.Impact, default))!;
            Assert.That(frame.ParamName, Is.EqualTo("frame"));
        }
    }
}
