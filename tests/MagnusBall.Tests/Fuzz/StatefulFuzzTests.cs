using System.Linq;
using MagnusBall.Fuzz;
using NUnit.Framework;

namespace MagnusBall.Tests.Fuzz
{
    /// <summary>
    /// Issue 15's fuzz of the library's stateful types, the short seeded subset: hostile calls into FlightStepper,
    /// FixedStepDriver, BallBatch, TrajectoryPredictor (reused buffers) and AimSolver. Every exception must be a documented
    /// one (an ArgumentException naming its parameter, or the documented InvalidOperationException) and finite input must
    /// leave no NaN and no non-finite state; after every call that throws, the object's observable state and the caller's
    /// buffers must be bitwise unchanged. The 10 s bound per call is measured by the long run (in Release; a Debug build
    /// on a loaded machine is several times slower), docs/robustness.md:
    /// `dotnet run -c Release --project benchmarks/MagnusBall.Benchmarks -- fuzz`.
    /// </summary>
    [TestFixture]
    public class StatefulFuzzTests
    {
        [TestCase(15)]
        [TestCase(2026)]
        public void HostileCalls_LeaveThrowingObjectsUnchanged_ThrowOnlyDocumentedExceptions_AndLeaveNoNaN(int seed)
        {
            StatefulFuzz fuzz = Run(seed, calls: 1_500);
            Assert.That(fuzz.ChangedAfterThrow, Is.Zero, Failure(fuzz, "changed"));
            Assert.That(fuzz.UndocumentedExceptions, Is.Zero, Failure(fuzz, "undocumented"));
            Assert.That(fuzz.UnnamedArgumentErrors, Is.Zero, Failure(fuzz, "unnamed"));
            Assert.That(fuzz.NaNs, Is.Zero, Failure(fuzz, "NaN"));
            Assert.That(fuzz.NonFiniteStates, Is.Zero, Failure(fuzz, "non-finite"));
            // The generator must reach every type and both sides: refusals and accepted calls.
            Assert.That(new[] { fuzz.StepperCalls, fuzz.DriverCalls, fuzz.BatchCalls, fuzz.PredictorCalls, fuzz.AimCalls }, Has.All.GreaterThan(5));
            Assert.That(fuzz.Throws, Is.InRange(fuzz.Calls / 100, fuzz.Calls / 2));
        }

        private static StatefulFuzz Run(int seed, int calls)
        {
            var fuzz = new StatefulFuzz(seed);
            fuzz.Run(calls);
            TestContext.Out.WriteLine(
                $"{fuzz.Calls} calls ({fuzz.StepperCalls} stepper, {fuzz.DriverCalls} driver, {fuzz.BatchCalls} batch, {fuzz.PredictorCalls} predictor, " +
                $"{fuzz.AimCalls} aim, {fuzz.ConstructorCalls} constructors): {fuzz.Throws} threw; {fuzz.ChangedAfterThrow} changed after a throw, " +
                $"{fuzz.UndocumentedExceptions} undocumented, {fuzz.UnnamedArgumentErrors} unnamed, {fuzz.NaNs} NaN, {fuzz.NonFiniteStates} non-finite, " +
                $"{fuzz.Hangs} over 10 s; slowest {fuzz.Slowest.TotalMilliseconds:F0} ms");
            foreach (var pair in fuzz.FirstByKind)
            {
                TestContext.Out.WriteLine($"first {pair.Key}: {pair.Value}");
            }

            return fuzz;
        }

        private static string Failure(StatefulFuzz fuzz, string kind) => fuzz.FirstByKind.TryGetValue(kind, out string? m) ? m : string.Empty;
    }
}
