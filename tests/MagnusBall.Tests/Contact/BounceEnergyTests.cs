using System;
using MagnusBall.Contact;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>No bounce gains energy: a seeded property test over random balls, planes, velocities and spins.</summary>
    [TestFixture]
    public class BounceEnergyTests
    {
        private const int Cases = 20_000;

        public static Surface[] Surfaces => Surface.All;

        [TestCaseSource(nameof(Surfaces))]
        public void KineticEnergy_NeverIncreases_AtABounce(Surface surface)
        {
            var model = new CrossBounce(surface);
            var random = new Random(20261124);
            int slides = 0, grips = 0;
            double worst = double.NegativeInfinity;
            for (int i = 0; i < Cases; i++)
            {
                var ball = new Ball(0.01 + 0.5 * random.NextDouble(), 0.015 + 0.12 * random.NextDouble(), 0.3 + 0.7 * random.NextDouble());
                Vector3d n = CrossBounceTests.RandomUnit(random);
                // Speeds 0-80 m/s, log-spread spins up to ~1000 rad/s in any direction.
                Vector3d v = CrossBounceTests.RandomUnit(random) * (80 * random.NextDouble());
                if (Vector3d.Dot(v, n) > 0)
                {
                    v = -v;
                }

                Vector3d w = CrossBounceTests.RandomUnit(random) * Math.Pow(10, 3 * random.NextDouble());
                BounceOutcome o = model.Bounce(ball, n, v, w);
                double before = Energy(ball, v, w);
                double after = Energy(ball, o.Velocity, o.AngularVelocity);
                Assert.That(o.Velocity.IsFinite && o.AngularVelocity.IsFinite, Is.True);
                // Rounding only: 1e-12 of the incoming energy.
                Assert.That(after, Is.LessThanOrEqualTo(before * (1 + 1e-12)), $"case {i}: v={v} w={w} n={n} {ball} -> {o}");
                worst = Math.Max(worst, (after - before) / before);
                if (o.Regime == BounceRegime.Slide)
                {
                    slides++;
                }
                else if (o.Regime == BounceRegime.Grip)
                {
                    grips++;
                }
            }

            TestContext.Out.WriteLine($"{surface.Name}: {slides} slides, {grips} grips, largest relative change {worst:E3}");
            if (surface.Contact.Friction > 0)
            {
                // Both regimes must have been exercised for the property to mean something.
                Assert.That(slides, Is.GreaterThan(Cases / 20));
                Assert.That(grips, Is.GreaterThan(Cases / 20));
            }
        }

        private static double Energy(Ball ball, in Vector3d v, in Vector3d w) =>
            0.5 * ball.Mass * v.LengthSquared + 0.5 * ball.MomentOfInertia * w.LengthSquared;
    }
}
