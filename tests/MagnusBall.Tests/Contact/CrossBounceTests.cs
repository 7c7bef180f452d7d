using System;
using MagnusBall.Contact;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// The Cross slide/grip bounce: its limits, the regimes and the switch between them, the worked cases of
    /// physics-references.md section 5, and what spin does to a bounce compared with a flat ball.
    /// </summary>
    [TestFixture]
    public class CrossBounceTests
    {
        private static readonly Ball Tennis = Ball.Tennis;

        private static Surface Custom(double ey, double mu, double ex, double d = 0) => new Surface("custom", ey, 0, mu, ex, d, 0);

        // ---- Limits ----

        [TestCase(Ball.SolidSphereInertiaFactor)]
        [TestCase(0.55)]
        [TestCase(Ball.ThinShellInertiaFactor)]
        public void Grip_WithoutSpinOffsetOrTangentialRestitution_KeepsOneOverOnePlusAlpha(double alpha)
        {
            var ball = new Ball(0.057, 0.033, alpha);
            var model = new CrossBounce(Custom(0.8, 0.9, 0));
            foreach (Court court in Court.All)
            {
                BounceOutcome o = court.Bounce(model, ball, 6, 50, 0);
                double vx1 = court.Forward(court.Velocity(6, 50));
                Assert.That(o.Regime, Is.EqualTo(BounceRegime.Grip), court.ToString());
                // Exact algebra in doubles: a few ulps of the operands.
                Assert.That(court.Forward(o.Velocity) / vx1, Is.EqualTo(1 / (1 + alpha)).Within(1e-14), court.ToString());
                // Gripping with e_x = 0 leaves it rolling: vx2 = R w2.
                Assert.That(court.Forward(o.Velocity), Is.EqualTo(ball.Radius * Vector3d.Dot(o.AngularVelocity, court.TopspinAxis)).Within(1e-13));
            }
        }

        [Test]
        public void Frictionless_KeepsTangentialVelocityAndSpin_ReversesNormal()
        {
            var random = new Random(5);
            foreach (double ey in new[] { 1.0, 0.7, 0.0 })
            {
                var model = new CrossBounce(ey == 1.0 ? Surface.Frictionless : Custom(ey, 0, 0.3, 0.01));
                for (int i = 0; i < 1000; i++)
                {
                    Vector3d n = RandomUnit(random);
                    Vector3d v = RandomUnit(random) * (0.1 + 40 * random.NextDouble());
                    if (Vector3d.Dot(v, n) > 0)
                    {
                        v = -v;
                    }

                    Vector3d w = RandomUnit(random) * (600 * random.NextDouble());
                    BounceOutcome o = model.Bounce(Tennis, n, v, w);
                    double vn = Vector3d.Dot(v, n);
                    Vector3d vt = v - n * vn;
                    // Only rounding of O(|v|) operands: 1e-12 relative to 40 m/s.
                    Assert.That(Vector3d.Distance(o.Velocity - n * Vector3d.Dot(o.Velocity, n), vt), Is.LessThan(1e-12 * 40));
                    Assert.That(Vector3d.Dot(o.Velocity, n), Is.EqualTo(-ey * vn).Within(1e-12 * 40));
                    // Spin is rebuilt from R (n x w) and w . n: rounding of O(600 rad/s) operands.
                    Assert.That(Vector3d.Distance(o.AngularVelocity, w), Is.LessThan(1e-12 * 600));
                    Assert.That(o.Regime, Is.EqualTo(BounceRegime.Slide));
                }
            }
        }

        [TestCaseSource(nameof(AllSurfaces))]
        public void NormalSpeed_ScalesByNormalRestitution(Surface surface)
        {
            var model = new CrossBounce(surface);
            foreach (double angle in new[] { 5.0, 16, 25, 45, 80, 90 })
            {
                foreach (double rpm in new[] { -3000.0, 0, 3000 })
                {
                    BounceOutcome o = Court.ZUp.Bounce(model, Tennis, 20, angle, rpm);
                    double vn = 20 * Math.Sin(angle * Math.PI / 180);
                    Assert.That(o.IncomingNormalSpeed, Is.EqualTo(vn).Within(1e-12));
                    Assert.That(o.NormalRestitution, Is.EqualTo(surface.Contact.NormalRestitutionAt(angle)).Within(1e-12));
                    Assert.That(Court.ZUp.Up(o.Velocity), Is.EqualTo(o.NormalRestitution * vn).Within(1e-12));
                }
            }

            Assert.That(Surface.Hard.Contact.NormalRestitutionAt(16), Is.EqualTo(0.87).Within(1e-15));
        }

        [Test]
        public void BallLeavingTheSurface_IsReturnedUnchanged()
        {
            var v = new Vector3d(10, 0, 0.5);
            var w = new Vector3d(1, 200, 3);
            BounceOutcome o = CrossBounce.Hard.Bounce(Tennis, Vector3d.UnitZ, v, w);
            Assert.That(o.Regime, Is.EqualTo(BounceRegime.None));
            Assert.That(o.Velocity, Is.EqualTo(v));
            Assert.That(o.AngularVelocity, Is.EqualTo(w));
        }

        // ---- Regimes ----

        [TestCaseSource(nameof(Courts))]
        public void FastShallowBall_Slides_SlowSteepBall_Grips(Surface surface)
        {
            var model = new CrossBounce(surface);
            BounceOutcome fast = Court.ZUp.Bounce(model, Tennis, 30, 10, 0);
            BounceOutcome slow = Court.ZUp.Bounce(model, Tennis, 8, 60, 0);
            Assert.That(fast.Regime, Is.EqualTo(BounceRegime.Slide));
            Assert.That(slow.Regime, Is.EqualTo(BounceRegime.Grip));
            // Sliding leaves the contact point still slipping forward: vx2 > R w2.
            Assert.That(Court.ZUp.Forward(fast.Velocity), Is.GreaterThan(Tennis.Radius * Vector3d.Dot(fast.AngularVelocity, Court.ZUp.TopspinAxis)));
        }

        [TestCaseSource(nameof(Courts))]
        public void RegimeSwitches_WhereTheSlidingSolutionEndsRolling(Surface surface)
        {
            // Raise the incoming angle at 20 m/s until the bounce stops sliding; bisect to the switch.
            var model = new CrossBounce(surface);
            double lo = 5, hi = 80;
            Assert.That(Court.ZUp.Bounce(model, Tennis, 20, lo, 0).Regime, Is.EqualTo(BounceRegime.Slide));
            Assert.That(Court.ZUp.Bounce(model, Tennis, 20, hi, 0).Regime, Is.EqualTo(BounceRegime.Grip));
            for (int i = 0; i < 60; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (Court.ZUp.Bounce(model, Tennis, 20, mid, 0).Regime == BounceRegime.Slide)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            // On the sliding side of the switch the contact point has just stopped slipping: vx2 = R w2.
            BounceOutcome edge = Court.ZUp.Bounce(model, Tennis, 20, lo, 0);
            double vx2 = Court.ZUp.Forward(edge.Velocity);
            double rw2 = Tennis.Radius * Vector3d.Dot(edge.AngularVelocity, Court.ZUp.TopspinAxis);
            BounceOutcome gripSide = Court.ZUp.Bounce(model, Tennis, 20, hi, 0);
            TestContext.Out.WriteLine(
                $"{surface.Name}: switch at {lo:F6} deg, vx2 {vx2:F6}, R w2 {rw2:F6}; across it vx2 jumps by " +
                $"{Court.ZUp.Forward(gripSide.Velocity) - vx2:F4} m/s, angle by {Court.ZUp.AngleDegrees(gripSide) - Court.ZUp.AngleDegrees(edge):F3} deg");
            // The bisection leaves the angle within ~1e-14 deg; the slip there is rounding-level.
            Assert.That(vx2 - rw2, Is.EqualTo(0).Within(1e-9));

            // With e_x = 0 the two branches meet at the switch: the bounce is continuous across it.
            var noRecoil = new CrossBounce(new Surface("no recoil", surface.Contact.NormalRestitution, surface.Contact.NormalRestitutionPerDegree,
                surface.Contact.Friction, 0, surface.Contact.ForceOffset, surface.Contact.ForceOffsetPerSpeed));
            BounceOutcome a = Court.ZUp.Bounce(noRecoil, Tennis, 20, lo, 0);
            BounceOutcome b = Court.ZUp.Bounce(noRecoil, Tennis, 20, hi, 0);
            Assert.That(a.Regime, Is.EqualTo(BounceRegime.Slide));
            Assert.That(b.Regime, Is.EqualTo(BounceRegime.Grip));
            // Angles differ by ~1e-14 deg across the bracket; the outcomes by the same order times the slope.
            Assert.That(Vector3d.Distance(a.Velocity, b.Velocity), Is.LessThan(1e-9));
            Assert.That(Vector3d.Distance(a.AngularVelocity, b.AngularVelocity), Is.LessThan(1e-7));
        }

        // ---- Worked cases (docs/references.md section 5, hard court, R 0.033, alpha 0.55) ----

        [TestCase(25, 16, 0, BounceRegime.Slide, 15.81, 22.3, 3408)]
        [TestCase(25, 16, 2000, BounceRegime.Grip, 16.58, 21.2, 4969)]
        [TestCase(20, 25, 0, BounceRegime.Grip, 11.58, 37.0, 3199)]
        public void WorkedCases_HardCourt(double speed, double angle, double rpm, BounceRegime regime, double speed2, double angle2, double rpm2)
        {
            foreach (Court court in Court.All)
            {
                BounceOutcome o = court.Bounce(CrossBounce.Hard, Tennis, speed, angle, rpm);
                TestContext.Out.WriteLine(
                    $"{court}: {o.Regime}, {court.Speed(o):F4} m/s at {court.AngleDegrees(o):F3} deg, {court.TopspinRpm(o):F1} rpm");
                Assert.That(o.Regime, Is.EqualTo(regime));
                // The published speeds are rounded to 0.01 m/s: half a unit.
                Assert.That(court.Speed(o), Is.EqualTo(speed2).Within(0.005));
                // Angles rounded to 0.1 deg.
                Assert.That(court.AngleDegrees(o), Is.EqualTo(angle2).Within(0.05));
                // Spins rounded to 1 rpm.
                Assert.That(court.TopspinRpm(o), Is.EqualTo(rpm2).Within(0.5));
                Assert.That(court.Left(o.Velocity), Is.EqualTo(0).Within(1e-12));
            }
        }

        // ---- Behaviour against a flat ball ----

        [TestCaseSource(nameof(Courts))]
        public void Topspin_LeavesFasterAndLower_Backspin_SlowerAndSteeper(Surface surface)
        {
            // 20 m/s at 30 deg: past the slide/grip switch on every court (17, 15 and 23 deg at 20 m/s), so the
            // flat ball grips and the spin changes how much its contact point slips.
            var model = new CrossBounce(surface);
            foreach (Court court in Court.All)
            {
                BounceOutcome flat = court.Bounce(model, Tennis, 20, 30, 0);
                BounceOutcome top = court.Bounce(model, Tennis, 20, 30, 2500);
                BounceOutcome back = court.Bounce(model, Tennis, 20, 30, -2500);
                TestContext.Out.WriteLine(
                    $"{surface.Name} {court}: top {top.Regime} {court.Speed(top):F2} m/s {court.AngleDegrees(top):F1} deg; " +
                    $"flat {flat.Regime} {court.Speed(flat):F2} {court.AngleDegrees(flat):F1}; back {back.Regime} {court.Speed(back):F2} {court.AngleDegrees(back):F1}");
                Assert.That(flat.Regime, Is.EqualTo(BounceRegime.Grip));
                Assert.That(court.Forward(top.Velocity), Is.GreaterThan(court.Forward(flat.Velocity) + 0.5));
                Assert.That(court.Forward(back.Velocity), Is.LessThan(court.Forward(flat.Velocity) - 0.5));
                Assert.That(court.Speed(top), Is.GreaterThan(court.Speed(flat)));
                Assert.That(court.Speed(back), Is.LessThan(court.Speed(flat)));
                Assert.That(court.AngleDegrees(top), Is.LessThan(court.AngleDegrees(flat) - 1));
                Assert.That(court.AngleDegrees(back), Is.GreaterThan(court.AngleDegrees(flat) + 1));
            }
        }

        [TestCaseSource(nameof(Courts))]
        public void WhileTheBallSlidesThroughout_ItsOutgoingVelocityDoesNotDependOnSpin(Surface surface)
        {
            // A property of Cross's model: sliding friction mu N does not depend on how fast the contact point slips,
            // so two balls that both slide throughout leave with the same velocity and differ only in spin.
            var model = new CrossBounce(surface);
            BounceOutcome flat = Court.ZUp.Bounce(model, Tennis, 30, 10, 0);
            BounceOutcome back = Court.ZUp.Bounce(model, Tennis, 30, 10, -3000);
            Assert.That(flat.Regime, Is.EqualTo(BounceRegime.Slide));
            Assert.That(back.Regime, Is.EqualTo(BounceRegime.Slide));
            Assert.That(Vector3d.Distance(flat.Velocity, back.Velocity), Is.LessThan(1e-12));
            Assert.That(Court.ZUp.TopspinRpm(back), Is.LessThan(Court.ZUp.TopspinRpm(flat) - 2000));
        }

        [TestCaseSource(nameof(Courts))]
        public void HeavyBackspin_AtASteepAngle_ComesBack(Surface surface)
        {
            var model = new CrossBounce(surface);
            foreach (Court court in Court.All)
            {
                BounceOutcome flat = court.Bounce(model, Tennis, 10, 60, 0);
                BounceOutcome back = court.Bounce(model, Tennis, 10, 60, -4000);
                TestContext.Out.WriteLine($"{surface.Name} {court}: vx2 flat {court.Forward(flat.Velocity):F2}, backspin {court.Forward(back.Velocity):F2} m/s");
                Assert.That(court.Forward(flat.Velocity), Is.GreaterThan(0));
                Assert.That(court.Forward(back.Velocity), Is.LessThan(-0.5));
            }
        }

        [TestCaseSource(nameof(Courts))]
        public void Sidespin_DeflectsTheBounceSideways_MirrorSymmetric(Surface surface)
        {
            var model = new CrossBounce(surface);
            foreach (Court court in Court.All)
            {
                double flat = court.Left(court.Bounce(model, Tennis, 25, 16, 1000, 0).Velocity);
                double plus = court.Left(court.Bounce(model, Tennis, 25, 16, 1000, 2000).Velocity);
                double minus = court.Left(court.Bounce(model, Tennis, 25, 16, 1000, -2000).Velocity);
                TestContext.Out.WriteLine($"{surface.Name} {court}: sideways {plus:F3} / {flat:F3} / {minus:F3} m/s");
                Assert.That(flat, Is.EqualTo(0).Within(1e-12));
                // Spin about +forward (right-handed) moves the contact point toward +left; friction pushes the ball right.
                Assert.That(plus, Is.LessThan(-0.3));
                Assert.That(minus, Is.EqualTo(-plus).Within(1e-12));
            }
        }

        [Test]
        public void SpinAboutTheNormal_IsKeptApart_AndDoesNotDeflect()
        {
            foreach (Court court in Court.All)
            {
                foreach (Surface surface in Surface.All)
                {
                    var model = new CrossBounce(surface);
                    Vector3d v = court.Velocity(20, 30);
                    Vector3d w = court.TopspinAxis * 150 + court.Frame.Up * 300;
                    BounceOutcome with = model.Bounce(Tennis, court.Frame.Up, v, w);
                    BounceOutcome without = model.Bounce(Tennis, court.Frame.Up, v, court.TopspinAxis * 150);
                    Assert.That(Vector3d.Dot(with.AngularVelocity, court.Frame.Up), Is.EqualTo(300).Within(1e-12));
                    Assert.That(Vector3d.Distance(with.Velocity, without.Velocity), Is.LessThan(1e-12));
                }
            }
        }

        // ---- Frames and planes ----

        [Test]
        public void TheSameBounce_GivesTheSameOutcome_InEveryFrame()
        {
            foreach (Surface surface in Surface.All)
            {
                var model = new CrossBounce(surface);
                BounceOutcome reference = Court.ZUp.Bounce(model, Tennis, 22, 18, 1800, -900);
                foreach (Court court in Court.All)
                {
                    BounceOutcome o = court.Bounce(model, Tennis, 22, 18, 1800, -900);
                    Assert.That(o.Regime, Is.EqualTo(reference.Regime));
                    // Same arithmetic on permuted components: rounding only.
                    Assert.That(court.Forward(o.Velocity), Is.EqualTo(Court.ZUp.Forward(reference.Velocity)).Within(1e-12), court.ToString());
                    Assert.That(court.Left(o.Velocity), Is.EqualTo(Court.ZUp.Left(reference.Velocity)).Within(1e-12), court.ToString());
                    Assert.That(court.Up(o.Velocity), Is.EqualTo(Court.ZUp.Up(reference.Velocity)).Within(1e-12), court.ToString());
                    Assert.That(court.TopspinRpm(o), Is.EqualTo(Court.ZUp.TopspinRpm(reference)).Within(1e-9), court.ToString());
                    Assert.That(court.SidespinRpm(o), Is.EqualTo(Court.ZUp.SidespinRpm(reference)).Within(1e-9), court.ToString());
                }
            }
        }

        [Test]
        public void ATiltedPlane_GivesTheRotatedOutcome()
        {
            // Rotate the whole bounce (normal, velocity, spin) by a proper rotation: the outcome rotates with it.
            var random = new Random(11);
            for (int i = 0; i < 200; i++)
            {
                Vector3d v = new Vector3d(15 * random.NextDouble() + 1, 8 * random.NextDouble() - 4, -10 * random.NextDouble() - 0.1);
                Vector3d w = RandomUnit(random) * (500 * random.NextDouble());
                Vector3d axis = RandomUnit(random);
                double angle = 2 * Math.PI * random.NextDouble();
                foreach (Surface surface in Surface.All)
                {
                    var model = new CrossBounce(surface);
                    BounceOutcome flat = model.Bounce(Tennis, Vector3d.UnitZ, v, w);
                    BounceOutcome tilted = model.Bounce(Tennis, Rotate(Vector3d.UnitZ, axis, angle), Rotate(v, axis, angle), Rotate(w, axis, angle));
                    Assert.That(tilted.Regime, Is.EqualTo(flat.Regime));
                    // Rounding in the rotation and the bounce: 1e-12 relative to |v| ~ 20 m/s and |w| ~ 1000 rad/s.
                    Assert.That(Vector3d.Distance(tilted.Velocity, Rotate(flat.Velocity, axis, angle)), Is.LessThan(1e-12 * 20));
                    Assert.That(Vector3d.Distance(tilted.AngularVelocity, Rotate(flat.AngularVelocity, axis, angle)), Is.LessThan(1e-12 * 1000));
                }
            }
        }

        // ---- Any ball ----

        [Test]
        public void WorksForOtherBalls()
        {
            var golf = new Ball(0.04593, 0.02134, 0.4);
            foreach (Ball ball in new[] { Ball.Soccer, golf })
            {
                foreach (Surface surface in Surface.All)
                {
                    BounceOutcome o = Court.ZUp.Bounce(new CrossBounce(surface), ball, 30, 40, 3000, 500);
                    Assert.That(o.Velocity.IsFinite && o.AngularVelocity.IsFinite, Is.True);
                    Assert.That(Court.ZUp.Up(o.Velocity), Is.GreaterThanOrEqualTo(0));
                }
            }
        }

        [TestCaseSource(nameof(Courts))]
        public void SlipThatTurns_MatchesANumericalIntegrationOfTheContact(Surface surface)
        {
            // With sidespin the offset torque (along the rolling direction) and friction (against the slip) are not
            // parallel, so the slip turns during contact. Integrate du/dq = a e1 - b u/|u| with 4,000 RK4 steps and
            // compare with the closed form the model uses (and with the straight slide it would be without the turn).
            var model = new CrossBounce(surface);
            var random = new Random(7);
            int compared = 0;
            double largestTurn = 0, largestDifference = 0;
            for (int i = 0; i < 200 && compared < 20; i++)
            {
                double speed = 15 + 15 * random.NextDouble(), angle = 8 + 14 * random.NextDouble();
                double top = 3000 * random.NextDouble() - 1000, side = 6000 * random.NextDouble() - 3000;
                BounceOutcome o = Court.ZUp.Bounce(model, Tennis, speed, angle, top, side);
                if (o.Regime != BounceRegime.Slide)
                {
                    continue;
                }

                // The same set-up the model makes (CrossBounce remarks), in the z-up frame: n = z.
                Vector3d n = Vector3d.UnitZ, v = Court.ZUp.Velocity(speed, angle);
                Vector3d w = Court.ZUp.TopspinAxis * Spin.FromRpm(top) + Court.ZUp.ForwardAxis * Spin.FromRpm(side);
                double vn = -v.Z, R = Tennis.Radius, alpha = Tennis.InertiaFactor;
                Vector3d vt = v + n * vn, omega = Vector3d.Cross(n, w) * R;
                Vector3d u = vt + omega, lambda = vt - omega * alpha, u1 = u;
                double J = (1 + o.NormalRestitution) * vn;
                double D = Math.Min(surface.Contact.ForceOffsetAt(v.Length), (1 + alpha) * surface.Contact.Friction * R / Math.Sqrt(2));
                double delta = Math.Min(D * J / R, lambda.Length);
                Vector3d e1 = lambda / lambda.Length;
                double a = delta / J, b = (1 + alpha) * surface.Contact.Friction, q = J / alpha;
                Func<Vector3d, Vector3d> f = x => e1 * a - x / x.Length * b;
                const int steps = 4_000;
                double h = q / steps;
                for (int k = 0; k < steps; k++)
                {
                    Vector3d k1 = f(u), k2 = f(u + k1 * (h / 2)), k3 = f(u + k2 * (h / 2)), k4 = f(u + k3 * h);
                    u += (k1 + k2 * 2 + k3 * 2 + k4) * (h / 6);
                }

                Vector3d lambda2 = lambda - e1 * delta;
                Vector3d expected = (lambda2 + u * alpha) / (1 + alpha) + n * (o.NormalRestitution * vn);
                double turn = Math.Acos(Math.Min(1, Vector3d.Dot(u, vt + omega) / (u.Length * (vt + omega).Length))) * 180 / Math.PI;
                // RK4 at 4,000 steps on a smooth path (the slip stays away from zero): error far below 1e-8 m/s.
                Assert.That(Vector3d.Distance(o.Velocity, expected), Is.LessThan(1e-8), $"case {i}: slip turned {turn:F2} deg");
                Vector3d straight = u1 + (e1 * a - u1 / u1.Length * b) * q;
                largestTurn = Math.Max(largestTurn, turn);
                largestDifference = Math.Max(largestDifference, Vector3d.Distance(expected, (lambda2 + straight * alpha) / (1 + alpha) + n * (o.NormalRestitution * vn)));
                compared++;
            }

            TestContext.Out.WriteLine(
                $"{surface.Name}: {compared} sliding bounces with sidespin compared; the slip turned up to {largestTurn:F2} deg, " +
                $"and a straight slide would have been off by up to {largestDifference:F4} m/s");
            Assert.That(compared, Is.EqualTo(20));
        }

        [TestCaseSource(nameof(AllSurfaces))]
        public void NearlyVerticalDrop_LeavesNearlyVertically(Surface surface)
        {
            // The offset torque resists rolling and cannot reverse it, so the bounce is continuous as the
            // tangential speed goes to zero: 1 um/s in, at most about that out.
            var model = new CrossBounce(surface);
            BounceOutcome o = model.Bounce(Tennis, Vector3d.UnitZ, new Vector3d(1e-6, 0, -10), Vector3d.Zero);
            double tangential = Math.Sqrt(o.Velocity.X * o.Velocity.X + o.Velocity.Y * o.Velocity.Y);
            Assert.That(tangential, Is.LessThanOrEqualTo(1e-6));
            Assert.That(Tennis.Radius * o.AngularVelocity.Length, Is.LessThanOrEqualTo(1e-6));
        }

        [Test]
        public void ExtremeButFiniteInput_GivesFiniteOutput()
        {
            double[] magnitudes = { 0, 1e-300, 1e-12, 1, 1e6, 1e100, 1e150 };
            foreach (Surface surface in Surface.All)
            {
                var model = new CrossBounce(surface);
                foreach (double speed in magnitudes)
                {
                    foreach (double spin in magnitudes)
                    {
                        foreach (Vector3d normal in new[] { Vector3d.UnitZ, new Vector3d(1e-150, 0, 1e-150), new Vector3d(3e100, -1e100, 2e100) })
                        {
                            Vector3d v = new Vector3d(0.8, 0.3, -0.5) * speed;
                            if (Vector3d.Dot(v, normal) > 0)
                            {
                                v = -v;
                            }

                            BounceOutcome o = model.Bounce(Tennis, normal, v, new Vector3d(0.2, -0.9, 0.4) * spin);
                            Assert.That(o.Velocity.IsFinite && o.AngularVelocity.IsFinite, Is.True, $"{surface.Name}: |v| {speed}, |w| {spin}, n {normal}");
                        }
                    }
                }
            }
        }

        [Test]
        public void ABounce_AllocatesNothing()
        {
            // Slides, grips and turning slips (side spin), on every preset.
            IBounceModel[] models = { CrossBounce.Hard, CrossBounce.Clay, CrossBounce.Grass, CrossBounce.Frictionless };
            Vector3d n = Vector3d.UnitZ;
            double sum = 0;
            Action bounces = () =>
            {
                for (int i = 0; i < 10_000; i++)
                {
                    var v = new Vector3d(5 + i % 25, 0.1 * (i % 7), -2 - i % 13);
                    var w = new Vector3d(40 * (i % 9) - 160, 30 * (i % 11) - 150, i % 5);
                    BounceOutcome o = models[i % models.Length].Bounce(Tennis, n, v, w);
                    sum += o.Velocity.X;
                }
            };

            Assert.That(Allocation.SteadyStateBytes(bounces), Is.EqualTo(0), "bytes allocated by 10,000 bounces after warm-up");

            Assert.That(double.IsFinite(sum), Is.True);
        }

        public static Surface[] AllSurfaces => Surface.All;

        public static Surface[] Courts => Surface.Courts;

        internal static Vector3d RandomUnit(Random random)
        {
            while (true)
            {
                var p = new Vector3d(2 * random.NextDouble() - 1, 2 * random.NextDouble() - 1, 2 * random.NextDouble() - 1);
                double l = p.Length;
                if (l > 0.1 && l <= 1)
                {
                    return p / l;
                }
            }
        }

        /// <summary>Rodrigues' rotation of v about a unit axis by angle (right-handed).</summary>
        private static Vector3d Rotate(Vector3d v, Vector3d axis, double angle) =>
            v * Math.Cos(angle) + Vector3d.Cross(axis, v) * Math.Sin(angle) + axis * (Vector3d.Dot(axis, v) * (1 - Math.Cos(angle)));
    }
}
