using MagnusBall.Fuzz;
using NUnit.Framework;

namespace MagnusBall.Tests.Fuzz
{
    /// <summary>
    /// Issue 15's fuzz test of the public physics API: 100,000 seeded calls (FlightModel.Derivative, the laws, Spin,
    /// Air and Atmosphere) with finite input over the whole range of doubles: no NaN, finite output for moderate
    /// input, and every refusal an ArgumentException naming its parameter. The long run (1,000,000 calls) is
    /// `dotnet run -c Release --project benchmarks/MagnusBall.Benchmarks -- fuzz`.
    /// </summary>
    [TestFixture]
    public class PhysicsFuzzTests
    {
        [Test]
        public void HostileCalls_NeverGiveNaN_OrAnUndocumentedException()
        {
            var fuzz = new PhysicsFuzz(seed: 15);
            fuzz.Run(100_000);
            TestContext.Out.WriteLine($"{fuzz.Calls} calls: {fuzz.ArgumentErrors} refused (ArgumentException), {fuzz.NaNs} NaN, " +
                                      $"{fuzz.InfiniteForModerate} infinite for moderate input, {fuzz.UnnamedArgumentErrors} unnamed, {fuzz.UndocumentedExceptions} other exceptions");
            Assert.That(fuzz.NaNs, Is.Zero, fuzz.FirstFailure);
            Assert.That(fuzz.InfiniteForModerate, Is.Zero, fuzz.FirstFailure);
            Assert.That(fuzz.UnnamedArgumentErrors, Is.Zero, fuzz.FirstFailure);
            Assert.That(fuzz.UndocumentedExceptions, Is.Zero, fuzz.FirstFailure);
            // The generator must reach both sides: refusals and accepted calls.
            Assert.That(fuzz.ArgumentErrors, Is.InRange(fuzz.Calls / 100, fuzz.Calls / 2));
        }
    }
}
