using System.Linq;
using MagnusBall.Fuzz;
using NUnit.Framework;

namespace MagnusBall.Tests.Fuzz
{
    /// <summary>
    /// Issue 40's contact shapes under the stateful fuzz, the short seeded subset (<see cref="StatefulFuzz.RunShapes"/>):
    /// FlightStepper, FixedStepDriver and TrajectoryPredictor built with 1-8 random shapes of every kind (and the SportShapes
    /// fixtures), driven with random states about the shapes and steps from 1e-5 s to 5 s. Every exception must be a documented
    /// one, a throwing call must leave its object bitwise unchanged, finite input must leave no NaN or non-finite state, and a ball
    /// that starts clear of a shape must never be found more than <see cref="StatefulFuzz.PenetrationTolerance"/> (1 cm + 1e-6 m,
    /// the documented sag) inside it. The long run: `dotnet run -c Release --project benchmarks/MagnusBall.Benchmarks -- fuzz-shapes`.
    /// </summary>
    [TestFixture]
    public class ShapeFuzzTests
    {
        [TestCase(40)]
        [TestCase(2026)]
        public void ShapeFlights_ThrowOnlyDocumentedExceptions_LeaveNoNaN_AndNeverTunnel(int seed)
        {
            StatefulFuzz fuzz = Run(seed, calls: 6_000);
            Assert.That(fuzz.ChangedAfterThrow, Is.Zero, Failure(fuzz, "changed"));
            Assert.That(fuzz.UndocumentedExceptions, Is.Zero, Failure(fuzz, "undocumented"));
            Assert.That(fuzz.UnnamedArgumentErrors, Is.Zero, Failure(fuzz, "unnamed"));
            Assert.That(fuzz.NaNs, Is.Zero, Failure(fuzz, "NaN"));
            Assert.That(fuzz.NonFiniteStates, Is.Zero, Failure(fuzz, "non-finite"));
            Assert.That(fuzz.Penetrations, Is.Zero, Failure(fuzz, "tunnel"));
            // The generator must reach every type, contacts and settling, and both sides: refusals and accepted calls.
            Assert.That(new[] { fuzz.ShapeStepperCalls, fuzz.ShapeDriverCalls, fuzz.ShapePredictorCalls }, Has.All.GreaterThan(5));
            Assert.That(fuzz.ShapeContacts, Is.GreaterThan(50));
            Assert.That(fuzz.PenetrationChecks, Is.GreaterThan(1000));
            Assert.That(fuzz.Throws, Is.InRange(fuzz.Calls / 100, fuzz.Calls / 2));
        }

        private static StatefulFuzz Run(int seed, int calls)
        {
            var fuzz = new StatefulFuzz(seed);
            fuzz.RunShapes(calls);
            TestContext.Out.WriteLine(
                $"{fuzz.Calls} calls ({fuzz.ShapeStepperCalls} stepper, {fuzz.ShapeDriverCalls} driver, {fuzz.ShapePredictorCalls} predictor, {fuzz.ConstructorCalls} constructors, " +
                $"{fuzz.ShapeSets} shape sets): {fuzz.Throws} threw; {fuzz.ShapeContacts} contacts ({fuzz.ShapeSettles} settled), {fuzz.PenetrationChecks} invariant checks; " +
                $"{fuzz.ChangedAfterThrow} changed after a throw, {fuzz.UndocumentedExceptions} undocumented, {fuzz.UnnamedArgumentErrors} unnamed, {fuzz.NaNs} NaN, " +
                $"{fuzz.NonFiniteStates} non-finite, {fuzz.Penetrations} tunnelled ({fuzz.ShallowPenetrations} shallow), {fuzz.Hangs} over 10 s; " +
                $"slowest {fuzz.Slowest.TotalMilliseconds:F0} ms");
            foreach (var pair in fuzz.FirstByKind)
            {
                TestContext.Out.WriteLine($"first {pair.Key}: {pair.Value}");
            }

            return fuzz;
        }

        private static string Failure(StatefulFuzz fuzz, string kind) => fuzz.FirstByKind.TryGetValue(kind, out string? m) ? m : string.Empty;
    }
}
