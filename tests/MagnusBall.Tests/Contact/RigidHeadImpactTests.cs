using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Swings;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// The impact with a rigid body whose centre of mass is offset from the contact (<see cref="RigidImpact"/>, used by
    /// <see cref="ClubSwing"/> with a <see cref="ClubHead"/>): the point-mass case is today's law bit for bit, the law
    /// conserves momentum and angular momentum and meets its own definitions (Newton's COR, the grip's slip recoil, the
    /// friction cone), creates no energy, is frame-agnostic and allocation-free, and refuses bad input.
    /// </summary>
    [TestFixture]
    public class RigidHeadImpactTests
    {
        private static readonly Ball Golf = new Ball(0.04593, 0.021335, Ball.SolidSphereInertiaFactor);
        private static readonly LaunchFrame ZUp = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);

        private static void AssertBitwise(in Vector3d expected, in Vector3d actual, string what)
        {
            Assert.That(BitConverter.DoubleToInt64Bits(actual.X), Is.EqualTo(BitConverter.DoubleToInt64Bits(expected.X)), what + ".X");
            Assert.That(BitConverter.DoubleToInt64Bits(actual.Y), Is.EqualTo(BitConverter.DoubleToInt64Bits(expected.Y)), what + ".Y");
            Assert.That(BitConverter.DoubleToInt64Bits(actual.Z), Is.EqualTo(BitConverter.DoubleToInt64Bits(expected.Z)), what + ".Z");
        }

        private static ClubSwing RandomDelivery(Random random, ClubHead head) => new ClubSwing(
            20 + 40 * random.NextDouble(), -5 + 60 * random.NextDouble(), -8 + 12 * random.NextDouble(), -10 + 20 * random.NextDouble(),
            -10 + 20 * random.NextDouble(), head, 0.6 + 0.3 * random.NextDouble(), random.NextDouble() < 0.2 ? 0.03 * random.NextDouble() : 0.4);

        [Test]
        public void PointMassHeads_GiveTodaysLaw_BitForBit()
        {
            // A head that cannot rotate (no lever, or infinite moments) goes through the point-mass law: the same bits as the
            // first constructor, which every existing club test pins.
            var random = new Random(16);
            var heads = new[]
            {
                ClubHead.PointMass(0.2),
                new ClubHead(0.2, 0.04, 0.003),                       // a lever, but infinite moments
                new ClubHead(0.2, 0, 0, 4e-4, 5e-4, 3e-4),            // moments, but no lever
            };
            for (int i = 0; i < 2000; i++)
            {
                ClubSwing old = RandomDelivery(random, ClubHead.PointMass(0.2));
                var reference = new ClubSwing(old.Speed, old.DynamicLoftDegrees, old.AttackAngleDegrees, old.FaceAngleDegrees, old.ClubPathDegrees,
                    0.2, old.Restitution, old.Friction).Hit(Golf, ZUp, Vector3d.Zero);
                foreach (ClubHead head in heads)
                {
                    SwingLaunch l = new ClubSwing(old.Speed, old.DynamicLoftDegrees, old.AttackAngleDegrees, old.FaceAngleDegrees, old.ClubPathDegrees,
                        head, old.Restitution, old.Friction).Hit(Golf, ZUp, Vector3d.Zero);
                    AssertBitwise(reference.Velocity, l.Velocity, "velocity");
                    AssertBitwise(reference.AngularVelocity, l.AngularVelocity, "spin");
                    Assert.That(l.Impact.Regime, Is.EqualTo(reference.Impact.Regime));
                }
            }
        }

        [Test]
        public void AVanishingLever_ConvergesToThePointMass()
        {
            // The rigid law's own arithmetic (not the point-mass branch) with a 1 nm lever: the point-mass law to 1e-9 of the
            // ball speed, in both regimes. This checks K's assembly and solve against Cross's closed forms.
            var random = new Random(1616);
            int slides = 0, grips = 0;
            for (int i = 0; i < 2000; i++)
            {
                ClubSwing club = RandomDelivery(random, ClubHead.PointMass(0.2));
                SwingLaunch point = club.Hit(Golf, ZUp, Vector3d.Zero);
                var rigid = new ClubSwing(club.Speed, club.DynamicLoftDegrees, club.AttackAngleDegrees, club.FaceAngleDegrees, club.ClubPathDegrees,
                    new ClubHead(0.2, 1e-9, 0, 4e-4, 5e-4, 3e-4), club.Restitution, club.Friction).Hit(Golf, ZUp, Vector3d.Zero);
                Assert.That(rigid.Impact.Regime, Is.EqualTo(point.Impact.Regime));
                Assert.That((rigid.Velocity - point.Velocity).Length, Is.LessThan(1e-9 * point.Speed));
                Assert.That((rigid.AngularVelocity - point.AngularVelocity).Length, Is.LessThan(1e-9 * point.Speed / Golf.Radius));
                if (point.Impact.Regime == BounceRegime.Slide)
                {
                    slides++;
                }
                else
                {
                    grips++;
                }
            }

            TestContext.Out.WriteLine($"{slides} slides, {grips} grips");
            Assert.That(slides, Is.GreaterThan(100));
            Assert.That(grips, Is.GreaterThan(100));
        }

        [Test]
        public void OnTheCgProjection_TheHeadIsAPointMassAlongTheNormal_AndLighterAlongTheFace()
        {
            // With the impact on the CG's projection (impact height 0) the normal force passes through the CG and only
            // friction turns the head, about the heel-toe axis with the lever D: K is diagonal, with 1/M along the normal and
            // 1/M + D^2/I along the face (in the D-plane). So a gripping, square delivery gives the point-mass normal velocity
            // and the point-mass friction impulse (and spin) scaled by K_tt(point)/K_tt(rigid), where
            // K_tt = (1/m)(1 + 1/alpha) + 1/M [+ D^2/I]. Closed form, to rounding (1e-12).
            double m = Golf.Mass, alpha = Golf.InertiaFactor, mass = 0.204, depth = 0.0423, inertia = 4.085e-4;
            double pointCompliance = (1 + 1 / alpha) / m + 1 / mass;
            double ratio = pointCompliance / (pointCompliance + depth * depth / inertia);
            foreach (double loft in new[] { 5.0, 10.8, 13.5, 25.0, 40.0 })
            {
                var point = new ClubSwing(50, loft, -1.3, headMass: mass).Hit(Golf, ZUp, Vector3d.Zero);
                var rigid = new ClubSwing(50, loft, -1.3, 0, 0, new ClubHead(mass, depth, 0, inertia, 5.679e-4, 2.843e-4)).Hit(Golf, ZUp, Vector3d.Zero);
                var club = new ClubSwing(50, loft, -1.3);
                Vector3d n = club.FaceNormal(ZUp);
                Assert.That(point.Impact.Regime, Is.EqualTo(BounceRegime.Grip));
                Assert.That(rigid.Impact.Regime, Is.EqualTo(BounceRegime.Grip));
                Assert.That(Vector3d.Dot(rigid.Impact.Impulse, n), Is.EqualTo(Vector3d.Dot(point.Impact.Impulse, n)).Within(1e-12 * point.Impact.Impulse.Length));
                Vector3d pointAlong = point.Impact.Impulse - n * Vector3d.Dot(point.Impact.Impulse, n);
                Vector3d rigidAlong = rigid.Impact.Impulse - n * Vector3d.Dot(rigid.Impact.Impulse, n);
                Assert.That((rigidAlong - pointAlong * ratio).Length, Is.LessThan(1e-12 * point.Impact.Impulse.Length), $"loft {loft}");
                Assert.That(rigid.SpinRate, Is.EqualTo(point.SpinRate * ratio).Within(1e-10 * point.SpinRate), $"loft {loft}");
            }

            TestContext.Out.WriteLine($"spin and friction impulse ratio {ratio:F4}; effective mass along the face {1 / (1 / mass + depth * depth / inertia):F4} kg");
        }

        private static (Vector3d N, RigidBodyInertia Body, Vector3d V, Vector3d W, ContactProperties Contact) RandomRigidImpact(Random random)
        {
            Vector3d n = CrossBounceTests.RandomUnit(random);
            Vector3d up = CrossBounceTests.RandomUnit(random);
            // Club-like and beyond: 0.1-0.4 kg, CG 0-60 mm behind, 0-20 mm off the normal, moments 1e-4 to 1e-3 kg m^2.
            Vector3d across = up - n * Vector3d.Dot(up, n);
            across = across.NormalizedOrZero();
            Vector3d lever = n * (0.06 * random.NextDouble()) + across * (0.02 * (2 * random.NextDouble() - 1));
            var body = new RigidBodyInertia(0.1 + 0.3 * random.NextDouble(), lever, Vector3d.Cross(n, across), across,
                Math.Pow(10, -4 + random.NextDouble()), Math.Pow(10, -4 + random.NextDouble()), Math.Pow(10, -4 + random.NextDouble()));
            Vector3d v = CrossBounceTests.RandomUnit(random) * (60 * random.NextDouble());
            if (Vector3d.Dot(v, n) > 0)
            {
                v = -v;
            }

            Vector3d w = CrossBounceTests.RandomUnit(random) * (500 * random.NextDouble());
            var contact = new ContactProperties(0.5 + 0.4 * random.NextDouble(), 1.0 * random.NextDouble(), 0.3 * random.NextDouble());
            return (n, body, v, w, contact);
        }

        [Test]
        public void TheLaw_ConservesMomentum_AndMeetsItsDefinitions()
        {
            // A ball hits a free rigid body at rest. Through Impact.Resolve (what ClubSwing calls): the ball's momentum changes
            // by the impulse, its angular momentum about the contact point does not change (the impulse acts there), and the
            // body's contact-point velocity change is the one of a rigid body receiving -P there. From the impulse, with the
            // body's motion derived here: the normal relative velocity leaves at -e of its incoming value (Newton's COR); a
            // grip leaves the slip at -e_x of its incoming value; a slide has |P_t| = mu P_n against the slip. All to
            // rounding (1e-9 of the quantity's scale; the arithmetic is a few dozen operations in double precision).
            var random = new Random(20261202);
            int slides = 0, grips = 0, fallbacks = 0;
            for (int i = 0; i < 20_000; i++)
            {
                (Vector3d n, RigidBodyInertia body, Vector3d v, Vector3d w, ContactProperties contact) = RandomRigidImpact(random);
                double m = Golf.Mass, r = Golf.Radius, ib = Golf.InertiaFactor * m * r * r;
                RigidImpact.Resolve(m, r, Golf.InertiaFactor, body, n, v, w, contact, out Vector3d p, out BounceRegime regime, out double e, out double vn, out bool coupled);
                Assert.That(regime, Is.Not.EqualTo(BounceRegime.None));
                if (!coupled)
                {
                    fallbacks++; // the two-step fallback: checked by the energy tests below
                    continue;
                }

                Vector3d v2 = v + p / m;
                Vector3d w2 = w + Vector3d.Cross(-n * r, p) / ib;
                Vector3d bodyV = -p / body.Mass;
                Vector3d bodyW = body.InverseInertia(Vector3d.Cross(body.Lever, -p));

                // The public path: the ball's centre at the origin, the body at rest with its face normal n.
                ImpactOutcome o = Impact.Resolve(Golf, Vector3d.Zero, v, w, ImpactBody.Moving(Vector3d.Zero, n, body.Mass), body, contact);
                Assert.That(o.Regime, Is.EqualTo(regime));
                // (ImpactBody normalizes n again, so the two agree to rounding of the ball's momentum, not bit for bit.)
                double momentum = p.Length + m * v.Length;
                Assert.That((o.Impulse - p).Length, Is.LessThan(1e-12 * momentum), "the same impulse");
                Assert.That(((o.Velocity - v) * m - o.Impulse).Length, Is.LessThan(1e-9 * momentum), "linear momentum");
                Vector3d before = Vector3d.Cross(n * r, v * m) + w * ib;
                Vector3d after = Vector3d.Cross(n * r, o.Velocity * m) + o.AngularVelocity * ib;
                Assert.That((after - before).Length, Is.LessThan(1e-9 * (m * v.Length * r + ib * w.Length + p.Length * r)), "angular momentum about the contact");
                Vector3d bodyContactChange = bodyV + Vector3d.Cross(bodyW, body.Lever);
                Assert.That((o.BodyVelocityChange - bodyContactChange).Length, Is.LessThan(1e-9 * (1 + bodyContactChange.Length)), "the body's contact-point change");

                Vector3d u1 = v + Vector3d.Cross(w, -n * r);
                Vector3d u2 = v2 + Vector3d.Cross(w2, -n * r) - (bodyV + Vector3d.Cross(bodyW, body.Lever));
                Assert.That(Vector3d.Dot(u2, n), Is.EqualTo(-e * Vector3d.Dot(u1, n)).Within(1e-9 * (1 + v.Length)), "Newton's COR");
                Vector3d slip1 = u1 - n * Vector3d.Dot(u1, n), slip2 = u2 - n * Vector3d.Dot(u2, n);
                double pn = Vector3d.Dot(p, n);
                Vector3d pt = p - n * pn;
                if (regime == BounceRegime.Grip)
                {
                    grips++;
                    Assert.That((slip2 + slip1 * contact.TangentialRestitution).Length, Is.LessThan(1e-9 * (1 + slip1.Length)), "grip recoil");
                }
                else
                {
                    slides++;
                    Assert.That(pt.Length, Is.EqualTo(contact.Friction * pn).Within(1e-9 * pn), "sliding friction");
                    Assert.That(Vector3d.Dot(pt, slip1), Is.LessThan(0), "friction opposes the slip");
                }
            }

            // Random lever directions and a spinning ball make a few slides whose fixed friction direction would push the
            // slip past zero (9 of 20,000 here): those take the two-step fallback.
            TestContext.Out.WriteLine($"{slides} slides, {grips} grips, {fallbacks} two-step fallbacks");
            Assert.That(slides, Is.GreaterThan(1000));
            Assert.That(grips, Is.GreaterThan(1000));
            Assert.That(fallbacks, Is.LessThan(20));
        }

        [Test]
        public void ClubDeliveries_TakeTheCoupledSolution_UnlessTheFaceIsNearlyFrictionless()
        {
            // Club geometry (a ball at rest, the head's CG behind the face, the lever in the face's own frame): over heads
            // around the measured driver and well beyond (100-400 g, CG 0-60 mm deep, impact -10 to +10 mm from the CG's
            // projection, moments 1e-4 to 1e-3 kg m^2), lofts -5 to 55 deg, face and path +-10 deg, e 0.6-0.9, mu 0.02-1 and
            // e_x 0-0.3, the coupled solution stands for every friction of 0.1 and more.
            var random = new Random(4242);
            int slides = 0, fallbacks = 0;
            for (int i = 0; i < 20_000; i++)
            {
                var head = new ClubHead(0.1 + 0.3 * random.NextDouble(), 0.06 * random.NextDouble(), 0.01 * (2 * random.NextDouble() - 1),
                    Math.Pow(10, -4 + random.NextDouble()), Math.Pow(10, -4 + random.NextDouble()), Math.Pow(10, -4 + random.NextDouble()));
                var club = new ClubSwing(20 + 40 * random.NextDouble(), -5 + 60 * random.NextDouble(), -8 + 12 * random.NextDouble(),
                    -10 + 20 * random.NextDouble(), -10 + 20 * random.NextDouble(), head, 0.6 + 0.3 * random.NextDouble(), 0.02 + 0.98 * random.NextDouble());
                Vector3d n = club.FaceNormal(ZUp);
                RigidBodyInertia body = head.Inertia(n, SwingGeometry.UpAcross(ZUp, n));
                var contact = new ContactProperties(club.Restitution, club.Friction, 0.3 * random.NextDouble());
                Vector3d relative = -club.PathDirection(ZUp) * club.Speed;
                RigidImpact.Resolve(Golf.Mass, Golf.Radius, Golf.InertiaFactor, body, n, relative, Vector3d.Zero, contact,
                    out _, out BounceRegime regime, out _, out _, out bool coupled);
                if (!coupled)
                {
                    // Only a ball sliding on a nearly frictionless face with the face well off the path (the slip turns as
                    // it shrinks, which the fixed friction direction cannot follow) takes the fallback.
                    fallbacks++;
                    Assert.That(regime, Is.EqualTo(BounceRegime.Slide), $"{club} {head}");
                    Assert.That(club.Friction, Is.LessThan(0.1), $"{club} {head}");
                    Assert.That(Math.Abs(club.FaceAngleDegrees - club.ClubPathDegrees), Is.GreaterThan(5), $"{club} {head}");
                }

                if (regime == BounceRegime.Slide)
                {
                    slides++;
                }
            }

            TestContext.Out.WriteLine($"{slides} slides of 20,000, {fallbacks} fallbacks");
            Assert.That(slides, Is.GreaterThan(100));
            Assert.That(fallbacks, Is.LessThan(20));
        }

        [Test]
        public void NoImpactWithAnyRigidBody_CreatesEnergy_ThroughTheFallbackToo()
        {
            // Bodies far outside any sport (1 mg to 10 kg, levers to 0.2 m along the normal and 0.05 m across, moments
            // 1e-9 to 1e-1 kg m^2), any COR, friction 0-2, e_x 0-1: where the coupling would make Newton's COR create energy
            // or a slide overshoot, the two-step fallback takes over; no case gains energy and the ball never leaves moving
            // into the face. Both paths are exercised (counted).
            var random = new Random(3);
            int fallbacks = 0;
            double worst = double.NegativeInfinity;
            double m = Golf.Mass, r = Golf.Radius, ib = Golf.InertiaFactor * m * r * r;
            for (int i = 0; i < 100_000; i++)
            {
                Vector3d n = CrossBounceTests.RandomUnit(random);
                Vector3d across = CrossBounceTests.RandomUnit(random);
                across = (across - n * Vector3d.Dot(across, n)).NormalizedOrZero();
                Vector3d lever = n * (0.2 * random.NextDouble()) + across * (0.05 * (2 * random.NextDouble() - 1));
                var body = new RigidBodyInertia(Math.Pow(10, -6 + 7 * random.NextDouble()), lever, Vector3d.Cross(n, across), across,
                    Math.Pow(10, -9 + 8 * random.NextDouble()), Math.Pow(10, -9 + 8 * random.NextDouble()), Math.Pow(10, -9 + 8 * random.NextDouble()));
                Vector3d v = CrossBounceTests.RandomUnit(random) * (60 * random.NextDouble());
                if (Vector3d.Dot(v, n) > 0)
                {
                    v = -v;
                }

                Vector3d w = CrossBounceTests.RandomUnit(random) * (500 * random.NextDouble());
                var contact = new ContactProperties(random.NextDouble(), 2 * random.NextDouble(), random.NextDouble());
                RigidImpact.Resolve(m, r, Golf.InertiaFactor, body, n, v, w, contact, out Vector3d p, out _, out _, out _, out bool coupled);
                if (!coupled)
                {
                    fallbacks++;
                }

                Vector3d v2 = v + p / m;
                Vector3d w2 = w + Vector3d.Cross(-n * r, p) / ib;
                Vector3d bodyV = -p / body.Mass;
                Vector3d bodyW = body.InverseInertia(Vector3d.Cross(body.Lever, -p));
                double before = 0.5 * m * v.LengthSquared + 0.5 * ib * w.LengthSquared;
                double after = 0.5 * m * v2.LengthSquared + 0.5 * ib * w2.LengthSquared
                               + 0.5 * body.Mass * bodyV.LengthSquared + 0.5 * Vector3d.Dot(bodyW, Inertia(body, bodyW));
                // Rounding of the energies (sums of a few squares): 1e-12 of the energy, 1e-15 J for a ball barely moving.
                worst = Math.Max(worst, (after - before) / Math.Max(before, 1e-300));
                Assert.That(after, Is.LessThanOrEqualTo(before * (1 + 1e-12) + 1e-15), $"case {i}, coupled {coupled}");
                Vector3d u2 = v2 + Vector3d.Cross(w2, -n * r) - (bodyV + Vector3d.Cross(bodyW, body.Lever));
                Assert.That(Vector3d.Dot(u2, n), Is.GreaterThanOrEqualTo(-1e-9 * (1 + v.Length)), $"case {i}: still approaching");
            }

            TestContext.Out.WriteLine($"{fallbacks} of 100,000 took the two-step fallback; closest to creating energy: {worst:E2} of it");
            Assert.That(fallbacks, Is.GreaterThan(100));
        }

        [Test]
        public void NoImpactWithARigidBodyAtRest_CreatesEnergy()
        {
            // The ball's kinetic energy (translation and spin) plus the body's (translation and rotation about its CG) never
            // grows. Newton's COR with a coupled K could create energy when the coupling is strong (docs/impacts.md gives the
            // condition); the random bodies here span club heads and beyond (0.1-0.4 kg, CG 0-60 mm deep and 0-20 mm off the
            // normal, moments 1e-4 to 1e-3 kg m^2, any face and ball direction, e 0.5-0.9, mu 0-1, e_x 0-0.3).
            var random = new Random(777);
            double worst = double.NegativeInfinity;
            for (int i = 0; i < 20_000; i++)
            {
                (Vector3d n, RigidBodyInertia body, Vector3d v, Vector3d w, ContactProperties contact) = RandomRigidImpact(random);
                double m = Golf.Mass, r = Golf.Radius, ib = Golf.InertiaFactor * m * r * r;
                RigidImpact.Resolve(m, r, Golf.InertiaFactor, body, n, v, w, contact, out Vector3d p, out _, out _, out _);
                Vector3d v2 = v + p / m;
                Vector3d w2 = w + Vector3d.Cross(-n * r, p) / ib;
                Vector3d bodyV = -p / body.Mass;
                Vector3d bodyW = body.InverseInertia(Vector3d.Cross(body.Lever, -p));
                double before = 0.5 * m * v.LengthSquared + 0.5 * ib * w.LengthSquared;
                double after = 0.5 * m * v2.LengthSquared + 0.5 * ib * w2.LengthSquared
                               + 0.5 * body.Mass * bodyV.LengthSquared + 0.5 * Vector3d.Dot(bodyW, Inertia(body, bodyW));
                worst = Math.Max(worst, (after - before) / Math.Max(before, 1e-300));
                // Rounding of the energies (sums of a few squares): 1e-12 of the energy, 1e-15 J for a ball barely moving.
                Assert.That(after, Is.LessThanOrEqualTo(before * (1 + 1e-12) + 1e-15), $"case {i}");
            }

            TestContext.Out.WriteLine($"closest to creating energy: {worst:E2} of it");
        }

        private static Vector3d Inertia(in RigidBodyInertia body, Vector3d w) =>
            Part(body.Axis1, body.InverseMoment1, w) + Part(body.Axis2, body.InverseMoment2, w) + Part(body.Axis3, body.InverseMoment3, w);

        private static Vector3d Part(in Vector3d axis, double inverse, in Vector3d w) => inverse == 0 ? Vector3d.Zero : axis * (Vector3d.Dot(axis, w) / inverse);

        [Test]
        public void ARigidHead_IsFrameAgnostic_AndAllocatesNothing()
        {
            // The same delivery in z-up and in Unity's y-up frame (forward +z): the same speed, launch angles and spin (1e-9).
            var yUp = new LaunchFrame(Vector3d.UnitY, Vector3d.UnitZ);
            var random = new Random(5);
            for (int i = 0; i < 500; i++)
            {
                ClubSwing club = RandomDelivery(random, new ClubHead(0.2, 0.06 * random.NextDouble(), 0.01 * (2 * random.NextDouble() - 1), 4e-4, 5.7e-4, 2.8e-4));
                SwingLaunch a = club.Hit(Golf, ZUp, Vector3d.Zero);
                SwingLaunch b = club.Hit(Golf, yUp, new Vector3d(3, 1, -2));
                Assert.That(b.Speed, Is.EqualTo(a.Speed).Within(1e-9 * a.Speed));
                Assert.That(b.ElevationDegrees, Is.EqualTo(a.ElevationDegrees).Within(1e-9));
                Assert.That(b.AzimuthDegrees, Is.EqualTo(a.AzimuthDegrees).Within(1e-9));
                Assert.That(b.SpinRate, Is.EqualTo(a.SpinRate).Within(1e-9 * (1 + a.SpinRate)));
                Assert.That(b.LaunchSpin.Topspin, Is.EqualTo(a.LaunchSpin.Topspin).Within(1e-9 * (1 + a.SpinRate)));
                Assert.That(b.LaunchSpin.Sidespin, Is.EqualTo(a.LaunchSpin.Sidespin).Within(1e-9 * (1 + a.SpinRate)));
            }

            var driver = new ClubSwing(50, 13, -1.3, 0, 0, ClubHead.MeasuredDriver);
            SwingLaunch warm = driver.Hit(Golf, ZUp, Vector3d.Zero);
            double sum = 0;
            Action hits = () =>
            {
                for (int i = 0; i < 4000; i++)
                {
                    sum += driver.Hit(Golf, ZUp, new Vector3d(i * 1e-3, 0, 0)).Speed;
                }
            };

            Assert.That(Allocation.SteadyStateBytes(hits), Is.EqualTo(0));
            Assert.That(sum, Is.GreaterThan(0));
            Assert.That(warm.IsHit);
        }

        [Test]
        public void ASquareHitOnTheCgProjection_ReachesTheSmashFactorBound_AndOffItFallsShort()
        {
            // The normal force through the CG (impact height 0) turns no head: the bound (1 + e)/(1 + m/M) is reached to
            // rounding. Off the CG's projection the normal force turns the head and the ball is slower.
            var club = new ClubSwing(50, 0, 0, 0, 0, ClubHead.MeasuredDriver);
            SwingLaunch centred = club.Hit(Golf, ZUp, Vector3d.Zero);
            Assert.That(centred.Speed / club.Speed, Is.EqualTo(club.SmashFactorBound(Golf)).Within(1e-12));
            Assert.That(club.SmashFactorBound(Golf), Is.EqualTo((1 + 0.83) / (1 + Golf.Mass / 0.204)).Within(1e-15));
            Assert.That(club.SmashFactorBound(Golf), Is.EqualTo(1.4937).Within(5e-5)); // as docs/impacts.md prints it
            foreach (double height in new[] { -0.01, -0.003, 0.003, 0.01 })
            {
                var off = new ClubHead(0.204, 0.0423, height, 4.085e-4, 5.679e-4, 2.843e-4);
                SwingLaunch l = new ClubSwing(50, 0, 0, 0, 0, off).Hit(Golf, ZUp, Vector3d.Zero);
                Assert.That(l.Speed / 50, Is.LessThan(club.SmashFactorBound(Golf)), $"impact {height * 1000} mm");
            }
        }

        [Test]
        public void ExtremeHeads_GiveFiniteLaunches()
        {
            // The corners of ClubHead's ranges (the lightest head with the smallest moments and the longest levers, the
            // heaviest, a point mass along one axis only) and club speeds from 0.01 to 1000 m/s: every launch is finite, and
            // the ball never leaves faster than twice the club speed plus rounding (in the head's initial frame the ball comes in
            // at the club speed and no impact with a body at rest raises its kinetic energy, so its speed there cannot grow).
            var heads = new[]
            {
                new ClubHead(1e-6, 0.2, 0.05, 1e-9, 1e-9, 1e-9),
                new ClubHead(1e-6, 0.2, -0.05, 1e-9, double.PositiveInfinity, double.PositiveInfinity),
                new ClubHead(1e6, 0.2, 0.05, 1e-9, 1e-9, 1e-9),
                new ClubHead(0.2, 0, 0.05, 1e-9, 1e6, double.PositiveInfinity),
            };
            var random = new Random(99);
            foreach (ClubHead head in heads)
            {
                foreach (double speed in new[] { 0.01, 1, 50, 1000 })
                {
                    for (int i = 0; i < 200; i++)
                    {
                        var club = new ClubSwing(speed, -10 + 90 * random.NextDouble(), -45 + 90 * random.NextDouble(), -45 + 90 * random.NextDouble(),
                            -45 + 90 * random.NextDouble(), head, random.NextDouble(), 2 * random.NextDouble());
                        SwingLaunch l = club.Hit(Golf, ZUp, Vector3d.Zero);
                        Assert.That(double.IsFinite(l.Velocity.X + l.Velocity.Y + l.Velocity.Z), $"{head} {club}");
                        Assert.That(double.IsFinite(l.AngularVelocity.X + l.AngularVelocity.Y + l.AngularVelocity.Z), $"{head} {club}");
                        Assert.That(l.Speed, Is.LessThanOrEqualTo(2 * speed * (1 + 1e-9)), $"{head} {club}");
                    }
                }
            }
        }

        [Test]
        public void BadInput_IsRefused_NamingTheParameter()
        {
            // Each refusal names the parameter and states the allowed range (or what was expected) in its message.
            static void Check(string name, string allowed, TestDelegate action)
            {
                ArgumentException ex = Assert.Catch<ArgumentException>(action)!;
                Assert.That(ex.ParamName, Is.EqualTo(name));
                Assert.That(ex.Message, Does.Contain(name));
                Assert.That(ex.Message, Does.Contain(allowed));
            }

            Check("mass", ">= 1E-06 kg", () => new ClubHead(0));
            Check("mass", ">= 1E-06 kg", () => new ClubHead(double.NaN));
            Check("mass", ">= 1E-06 kg", () => new ClubHead(1e-7));
            Check("mass", ">= 1E-06 kg", () => new ClubHead(double.PositiveInfinity));
            Check("mass", ">= 1E-06 kg", () => ClubHead.PointMass(-0.2));
            Check("mass", ">= 1E-06 kg", () => ClubHead.PointMass(double.NaN));
            Check("centerOfGravityDepth", "[0, 0.2]", () => new ClubHead(0.2, -0.001));
            Check("centerOfGravityDepth", "[0, 0.2]", () => new ClubHead(0.2, 0.3));
            Check("centerOfGravityDepth", "[0, 0.2]", () => new ClubHead(0.2, double.PositiveInfinity));
            Check("impactHeight", "[-0.05, 0.05]", () => new ClubHead(0.2, 0.04, 0.06));
            Check("impactHeight", "[-0.05, 0.05]", () => new ClubHead(0.2, 0.04, double.NaN));
            Check("heelToeInertia", ">= 1E-09 kg m^2", () => new ClubHead(0.2, 0.04, 0, 1e-10));
            Check("heelToeInertia", ">= 1E-09 kg m^2", () => new ClubHead(0.2, 0.04, 0, 0));
            Check("verticalInertia", ">= 1E-09 kg m^2", () => new ClubHead(0.2, 0.04, 0, 4e-4, -1));
            Check("faceNormalInertia", ">= 1E-09 kg m^2", () => new ClubHead(0.2, 0.04, 0, 4e-4, 5e-4, double.NaN));
            Check("faceNormalInertia", ">= 1E-09 kg m^2", () => new ClubHead(0.2, 0.04, 0, 4e-4, 5e-4, double.NegativeInfinity));
            Check("head", "mass > 0 kg", () => new ClubSwing(50, 10, 0, 0, 0, default(ClubHead)));
            Check("speed", "> 0", () => new ClubSwing(double.NaN, 10, 0, 0, 0, ClubHead.MeasuredDriver));
            Check("dynamicLoftDegrees", "[-10, 80]", () => new ClubSwing(50, 90, 0, 0, 0, ClubHead.MeasuredDriver));
            Check("attackAngleDegrees", "[-45, 45]", () => new ClubSwing(50, 10, double.PositiveInfinity, 0, 0, ClubHead.MeasuredDriver));
            Check("faceAngleDegrees", "[-45, 45]", () => new ClubSwing(50, 10, 0, 46, 0, ClubHead.MeasuredDriver));
            Check("clubPathDegrees", "[-45, 45]", () => new ClubSwing(50, 10, 0, 0, -46, ClubHead.MeasuredDriver));
            Check("restitution", "[0, 1]", () => new ClubSwing(50, 10, 0, 0, 0, ClubHead.MeasuredDriver, 1.1));
            Check("friction", ">= 0", () => new ClubSwing(50, 10, 0, 0, 0, ClubHead.MeasuredDriver, 0.8, -0.1));
            Check("frame", "LaunchFrame", () => new ClubSwing(50, 10, 0, 0, 0, ClubHead.MeasuredDriver).Hit(Golf, default, Vector3d.Zero));
            Check("position", "finite", () => new ClubSwing(50, 10, 0, 0, 0, ClubHead.MeasuredDriver).Hit(Golf, ZUp, new Vector3d(double.NaN, 0, 0)));
        }
    }
}
