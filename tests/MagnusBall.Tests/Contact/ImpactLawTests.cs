using System;
using MagnusBall.Contact;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// The general impact law (<see cref="Impact"/>): the ground bounce through it is the old bounce bit for bit,
    /// no impact with a body at rest creates energy, the apparent COR of a head-on impact, frames, bad input, no allocation.
    /// </summary>
    [TestFixture]
    public class ImpactLawTests
    {
        private const int Cases = 20_000;

        private static Surface RandomSurface(Random random) => new Surface(
            "random", random.NextDouble(), 0.01 * random.NextDouble(), 1.2 * random.NextDouble(), random.NextDouble(),
            0.01 * random.NextDouble(), 1e-3 * random.NextDouble());

        private static Ball RandomBall(Random random) =>
            new Ball(0.01 + 0.5 * random.NextDouble(), 0.015 + 0.12 * random.NextDouble(), 0.3 + 0.7 * random.NextDouble());

        private static (Vector3d N, Vector3d V, Vector3d W) RandomHit(Random random)
        {
            Vector3d n = CrossBounceTests.RandomUnit(random);
            Vector3d v = CrossBounceTests.RandomUnit(random) * (80 * random.NextDouble());
            if (Vector3d.Dot(v, n) > 0 && random.NextDouble() < 0.95)
            {
                v = -v; // keep 5 % moving away (no impact) to check that path too
            }

            Vector3d w = CrossBounceTests.RandomUnit(random) * Math.Pow(10, 3 * random.NextDouble());
            return (n, v, w);
        }

        private static void AssertBitwise(double expected, double actual, string what)
        {
            Assert.That(BitConverter.DoubleToInt64Bits(actual), Is.EqualTo(BitConverter.DoubleToInt64Bits(expected)), $"{what}: {expected:R} vs {actual:R}");
        }

        private static void AssertBitwise(in Vector3d expected, in Vector3d actual, string what)
        {
            AssertBitwise(expected.X, actual.X, what + ".X");
            AssertBitwise(expected.Y, actual.Y, what + ".Y");
            AssertBitwise(expected.Z, actual.Z, what + ".Z");
        }

        [Test]
        public void GroundBounce_ThroughTheGeneralLaw_IsTheOldBounce_BitForBit()
        {
            // ReferenceCrossBounce is the bounce as it was before the law existed (a frozen copy of the old code).
            var random = new Random(20261201);
            int slides = 0, grips = 0, none = 0;
            foreach (Surface preset in Surface.All)
            {
                Compare(preset, random, ref slides, ref grips, ref none);
            }

            for (int s = 0; s < 20; s++)
            {
                Compare(RandomSurface(random), random, ref slides, ref grips, ref none);
            }

            TestContext.Out.WriteLine($"{slides} slides, {grips} grips, {none} no-contact cases identical to the bit");
            Assert.That(slides, Is.GreaterThan(10_000));
            Assert.That(grips, Is.GreaterThan(10_000));
            Assert.That(none, Is.GreaterThan(1_000));
        }

        private static void Compare(Surface surface, Random random, ref int slides, ref int grips, ref int none)
        {
            var reference = new ReferenceCrossBounce(surface);
            var model = new CrossBounce(surface);
            for (int i = 0; i < 5_000; i++)
            {
                Ball ball = RandomBall(random);
                (Vector3d n, Vector3d v, Vector3d w) = RandomHit(random);
                Vector3d tilted = n * (0.5 + 2 * random.NextDouble()); // not unit: both normalise
                BounceOutcome expected = reference.Bounce(ball, tilted, v, w);
                BounceOutcome actual = model.Bounce(ball, tilted, v, w);
                AssertBitwise(expected.Velocity, actual.Velocity, $"case {i} velocity");
                AssertBitwise(expected.AngularVelocity, actual.AngularVelocity, $"case {i} spin");
                AssertBitwise(expected.NormalRestitution, actual.NormalRestitution, $"case {i} e_y");
                AssertBitwise(expected.IncomingNormalSpeed, actual.IncomingNormalSpeed, $"case {i} vn");
                Assert.That(actual.Regime, Is.EqualTo(expected.Regime));

                // The public law with an immovable body at rest gives the same values (its frame shift adds +0, which
                // can only turn a -0 into +0: equal as numbers, so compared with ==).
                ImpactOutcome law = Impact.Resolve(ball, Vector3d.Zero, v, w, ImpactBody.Immovable(tilted), surface.Contact);
                Assert.That(law.Velocity == expected.Velocity && law.AngularVelocity == expected.AngularVelocity, Is.True, $"case {i}: {law} vs {expected}");
                Assert.That(law.Regime, Is.EqualTo(expected.Regime));
                switch (expected.Regime)
                {
                    case BounceRegime.Slide: slides++; break;
                    case BounceRegime.Grip: grips++; break;
                    default: none++; break;
                }
            }
        }

        [Test]
        public void WorkedCases_StillGiveThePublishedDigits()
        {
            // docs/references.md section 5 (hard court): 25 m/s at 16 deg without spin slides to 15.81 m/s at 22.3 deg, 3408 rpm.
            BounceOutcome o = Court.ZUp.Bounce(CrossBounce.Hard, Ball.Tennis, 25, 16, 0);
            Assert.That(o.Regime, Is.EqualTo(BounceRegime.Slide));
            Assert.That(Court.ZUp.Speed(o), Is.EqualTo(15.81).Within(0.005)); // half a unit of the published rounding
            Assert.That(Court.ZUp.AngleDegrees(o), Is.EqualTo(22.3).Within(0.05));
            Assert.That(Court.ZUp.TopspinRpm(o), Is.EqualTo(3408).Within(0.5));
        }

        [Test]
        public void NoImpactWithABodyAtRest_CreatesEnergy()
        {
            // Seeded property test: random ball, plane, velocity, spin, contact parameters and effective mass
            // (10 g to 100 kg, or immovable). The ball never leaves with more kinetic energy than it came with, and the
            // ball plus the body's effective point mass never gain energy.
            var random = new Random(16);
            int slides = 0, grips = 0;
            double worst = double.NegativeInfinity;
            for (int i = 0; i < Cases; i++)
            {
                Ball ball = RandomBall(random);
                (Vector3d n, Vector3d v, Vector3d w) = RandomHit(random);
                double mass = random.NextDouble() < 0.1 ? double.PositiveInfinity : Math.Pow(10, -2 + 4 * random.NextDouble());
                Surface surface = RandomSurface(random);
                ImpactOutcome o = Impact.Resolve(ball, Vector3d.Zero, v, w, ImpactBody.Moving(Vector3d.Zero, n, mass), surface.Contact);
                double before = BallEnergy(ball, v, w);
                double after = BallEnergy(ball, o.Velocity, o.AngularVelocity);
                double body = double.IsPositiveInfinity(mass) ? 0 : 0.5 * mass * o.BodyVelocityChange.LengthSquared;
                Assert.That(o.Velocity.IsFinite && o.AngularVelocity.IsFinite, Is.True);
                // Rounding only: 1e-12 of the incoming energy.
                Assert.That(after, Is.LessThanOrEqualTo(before * (1 + 1e-12) + 1e-300), $"case {i}: ball gained energy, {o}");
                Assert.That(after + body, Is.LessThanOrEqualTo(before * (1 + 1e-12) + 1e-300), $"case {i}: ball + body gained energy, {o}");
                if (before > 0 && o.Regime != BounceRegime.None)
                {
                    worst = Math.Max(worst, (after + body - before) / before);
                }

                slides += o.Regime == BounceRegime.Slide ? 1 : 0;
                grips += o.Regime == BounceRegime.Grip ? 1 : 0;
            }

            TestContext.Out.WriteLine($"{slides} slides, {grips} grips; largest relative change of ball + body energy {worst:E3}");
            Assert.That(slides, Is.GreaterThan(Cases / 20));
            Assert.That(grips, Is.GreaterThan(Cases / 20));
        }

        [Test]
        public void AMovingBody_NeverCreatesEnergyInTheCentreOfMassFrame()
        {
            // A moving body gives the ball energy, but the ball and the body's effective point mass together never gain
            // kinetic energy (the law's invariant, docs/impacts.md), whatever the body's motion.
            var random = new Random(1616);
            for (int i = 0; i < Cases; i++)
            {
                Ball ball = RandomBall(random);
                (Vector3d n, Vector3d v, Vector3d w) = RandomHit(random);
                double mass = Math.Pow(10, -2 + 4 * random.NextDouble());
                Vector3d bodyVelocity = CrossBounceTests.RandomUnit(random) * (60 * random.NextDouble());
                var body = ImpactBody.Moving(bodyVelocity, n, mass);
                ImpactOutcome o = Impact.Resolve(ball, Vector3d.Zero, v, w, body, RandomSurface(random).Contact);
                double before = BallEnergy(ball, v, w) + 0.5 * mass * bodyVelocity.LengthSquared;
                double after = BallEnergy(ball, o.Velocity, o.AngularVelocity) + 0.5 * mass * (bodyVelocity + o.BodyVelocityChange).LengthSquared;
                Assert.That(after, Is.LessThanOrEqualTo(before * (1 + 1e-12)), $"case {i}: {o}");
                // Momentum: the body lost what the ball gained (to rounding of O(m v)).
                Assert.That((o.Impulse + o.BodyVelocityChange * mass).Length, Is.LessThan(1e-12 * (1 + o.Impulse.Length)));
            }
        }

        [TestCase(0.85, 0.20)]
        [TestCase(0.5, 0.58)]
        [TestCase(0.83, 0.2)]
        [TestCase(1.0, 1.0)]
        public void HeadOn_GivesTheApparentRestitutionFormula(double e, double bodyMass)
        {
            // Brody, Cross & Lindsey ch. 11: v_out = e_A v_in + (1 + e_A) V with e_A = (e - m/M)/(1 + m/M).
            Ball ball = Ball.Tennis;
            double kappa = ball.Mass / bodyMass;
            double apparent = (e - kappa) / (1 + kappa);
            foreach (double vIn in new[] { 0.0, 5, 20 })
            {
                foreach (double vBody in new[] { 0.0, 10, 37 })
                {
                    // Ball moves along -x into a face moving along +x; normal +x.
                    var body = ImpactBody.Moving(new Vector3d(vBody, 0, 0), Vector3d.UnitX, bodyMass);
                    var contact = new ContactProperties(e, 0.4);
                    if (vIn + vBody == 0)
                    {
                        continue;
                    }

                    ImpactOutcome o = Impact.Resolve(ball, Vector3d.Zero, new Vector3d(-vIn, 0, 0), Vector3d.Zero, body, contact);
                    // Exact algebra in doubles: a few ulps of 100 m/s.
                    Assert.That(o.Velocity.X, Is.EqualTo(apparent * vIn + (1 + apparent) * vBody).Within(1e-12));
                    Assert.That(o.Velocity.Y, Is.EqualTo(0));
                    Assert.That(o.AngularVelocity.Length, Is.EqualTo(0));
                }
            }
        }

        [Test]
        public void TheLaw_IsGalileanAndRotationInvariant()
        {
            var random = new Random(77);
            for (int i = 0; i < 500; i++)
            {
                Ball ball = RandomBall(random);
                (Vector3d n, Vector3d v, Vector3d w) = RandomHit(random);
                Vector3d bodyVelocity = CrossBounceTests.RandomUnit(random) * (30 * random.NextDouble());
                Vector3d bodySpin = CrossBounceTests.RandomUnit(random) * (30 * random.NextDouble());
                Vector3d centre = CrossBounceTests.RandomUnit(random) * 3;
                var body = new ImpactBody(centre + n * 0.1, bodyVelocity, bodySpin, n, 0.05 + random.NextDouble());
                ContactProperties contact = RandomSurface(random).Contact;
                ImpactOutcome o = Impact.Resolve(ball, centre, v, w, body, contact);

                // A constant velocity added to everything is added to the outcome.
                Vector3d shift = CrossBounceTests.RandomUnit(random) * 20;
                var shiftedBody = new ImpactBody(body.Point, bodyVelocity + shift, bodySpin, n, body.EffectiveMass);
                ImpactOutcome s = Impact.Resolve(ball, centre, v + shift, w, shiftedBody, contact);
                // Rounding of O(100 m/s) sums.
                Assert.That(Vector3d.Distance(s.Velocity, o.Velocity + shift), Is.LessThan(1e-10));
                Assert.That(Vector3d.Distance(s.AngularVelocity, o.AngularVelocity), Is.LessThan(1e-9 * (1 + o.SpinRate)));

                // A rotation of everything rotates the outcome (a proper rotation about a random axis).
                Vector3d axis = CrossBounceTests.RandomUnit(random);
                double angle = 2 * Math.PI * random.NextDouble();
                Vector3d R(Vector3d x) => Rotate(x, axis, angle);
                var rotatedBody = new ImpactBody(R(body.Point), R(bodyVelocity), R(bodySpin), R(n), body.EffectiveMass);
                ImpactOutcome r = Impact.Resolve(ball, R(centre), R(v), R(w), rotatedBody, contact);
                Assert.That(Vector3d.Distance(r.Velocity, R(o.Velocity)), Is.LessThan(1e-10 * (1 + o.Speed)));
                Assert.That(Vector3d.Distance(r.AngularVelocity, R(o.AngularVelocity)), Is.LessThan(1e-9 * (1 + o.SpinRate)));
            }
        }

        [Test]
        public void Resolve_AllocatesNothing()
        {
            var body = ImpactBody.Moving(new Vector3d(30, 5, 0), new Vector3d(1, 0.2, 0), 0.3);
            var contact = new ContactProperties(0.85, 0.4);
            ImpactOutcome o = default;
            Action resolves = () =>
            {
                for (int i = 0; i < 10_000; i++)
                {
                    o = Impact.Resolve(Ball.Tennis, Vector3d.Zero, new Vector3d(-10 - 1e-3 * i, 0, 0), new Vector3d(0, 0, 100), body, contact);
                }
            };

            Assert.That(Allocation.SteadyStateBytes(resolves), Is.EqualTo(0));
            Assert.That(o.Regime, Is.Not.EqualTo(BounceRegime.None));
        }

        [Test]
        public void BadInput_IsRefused_NamingTheParameter()
        {
            var n = Vector3d.UnitX;
            void Check(string name, TestDelegate action)
            {
                var e = (ArgumentException)Assert.Throws(Is.InstanceOf<ArgumentException>(), action)!;
                Assert.That(e.ParamName, Is.EqualTo(name));
                Assert.That(e.Message, Does.Contain(name));
            }

            Check("effectiveMass", () => ImpactBody.Moving(Vector3d.Zero, n, 0));
            Check("effectiveMass", () => ImpactBody.Moving(Vector3d.Zero, n, -1));
            Check("effectiveMass", () => ImpactBody.Moving(Vector3d.Zero, n, double.NaN));
            Check("normal", () => ImpactBody.Moving(Vector3d.Zero, Vector3d.Zero, 1));
            Check("velocity", () => ImpactBody.Moving(new Vector3d(double.NaN, 0, 0), n, 1));
            Check("angularVelocity", () => new ImpactBody(Vector3d.Zero, Vector3d.Zero, new Vector3d(0, double.PositiveInfinity, 0), n, 1));
            Check("point", () => new ImpactBody(new Vector3d(0, double.NaN, 0), Vector3d.Zero, Vector3d.Zero, n, 1));
            Check("normalRestitution", () => new ContactProperties(1.2, 0.4));
            Check("friction", () => new ContactProperties(0.8, -0.1));
            Check("tangentialRestitution", () => new ContactProperties(0.8, 0.4, 2));
            Check("forceOffset", () => new ContactProperties(0.8, 0.4, 0, -1));
            Check("normalRestitutionPerDegree", () => new ContactProperties(0.8, 0.4, 0, 0, double.NaN));
            Check("forceOffsetPerSpeed", () => new ContactProperties(0.8, 0.4, 0, 0, 0, -1));
            var good = ImpactBody.Immovable(n);
            var contact = new ContactProperties(0.8, 0.4);
            Check("ball", () => Impact.Resolve(null!, Vector3d.Zero, -n, Vector3d.Zero, good, contact));
            Check("position", () => Impact.Resolve(Ball.Tennis, new Vector3d(double.NaN, 0, 0), -n, Vector3d.Zero, good, contact));
            Check("velocity", () => Impact.Resolve(Ball.Tennis, Vector3d.Zero, new Vector3d(double.NaN, 0, 0), Vector3d.Zero, good, contact));
            Check("angularVelocity", () => Impact.Resolve(Ball.Tennis, Vector3d.Zero, -n, new Vector3d(double.NaN, 0, 0), good, contact));
            Check("body", () => Impact.Resolve(Ball.Tennis, Vector3d.Zero, -n, Vector3d.Zero, default, contact));
        }

        internal static double BallEnergy(Ball ball, in Vector3d v, in Vector3d w) =>
            0.5 * ball.Mass * v.LengthSquared + 0.5 * ball.MomentOfInertia * w.LengthSquared;

        private static Vector3d Rotate(in Vector3d x, in Vector3d axis, double angle)
        {
            // Rodrigues' formula, proper rotation.
            double c = Math.Cos(angle), s = Math.Sin(angle);
            return x * c + Vector3d.Cross(axis, x) * s + axis * (Vector3d.Dot(axis, x) * (1 - c));
        }
    }
}
