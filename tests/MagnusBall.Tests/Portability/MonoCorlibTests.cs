using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using System.Reflection.Emit;
using NUnit.Framework;

namespace MagnusBall.Tests.Portability
{
    /// <summary>
    /// The library must run on Debian's Mono 6.8 unpatched. That corlib declares ReadOnlySpan's indexer and its
    /// enumerator's Current without the modreq(InAttribute) of a readonly-ref return, so a call to either from
    /// the netstandard2.1 library throws MissingMethodException there (see SpanView). This scans the library's
    /// IL on any runtime, so a new call fails here, not only in the Mono run (tools/test-mono.sh).
    /// </summary>
    public class MonoCorlibTests
    {
        private static readonly Dictionary<short, OpCode> OpCodesByValue = typeof(OpCodes)
            .GetFields(BindingFlags.Public | BindingFlags.Static)
            .Select(f => (OpCode)f.GetValue(null)!)
            .ToDictionary(o => o.Value);

        [Test]
        public void Library_NeverCallsTheReadOnlySpanIndexer_OrItsEnumerator()
        {
            Assembly library = typeof(Vector3d).Assembly;
            var offenders = new List<string>();
            int calls = 0;
            foreach (Type type in library.GetTypes())
            {
                const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
                IEnumerable<MethodBase> methods = type.GetMethods(all).Cast<MethodBase>().Concat(type.GetConstructors(all));
                foreach (MethodBase method in methods)
                {
                    foreach (MethodBase callee in Callees(method))
                    {
                        calls++;
                        Type? owner = callee.DeclaringType;
                        if (owner is { IsGenericType: true } && (owner.GetGenericTypeDefinition() == typeof(ReadOnlySpan<>)
                            || owner.GetGenericTypeDefinition() == typeof(ReadOnlySpan<>.Enumerator))
                            && (callee.Name == "get_Item" || callee.Name == "get_Current" || callee.Name == "GetEnumerator"))
                        {
                            offenders.Add($"{type.FullName}.{method.Name} calls {owner.Name}.{callee.Name}");
                        }
                    }
                }
            }

            // The scan must see the library's calls at all (thousands), or it would pass by reading nothing.
            Assert.That(calls, Is.GreaterThan(1000));
            Assert.That(offenders, Is.Empty, "use SpanView.Of(span)[i] (Mono 6.8's corlib lacks these):\n" + string.Join("\n", offenders));
        }

#if NETCOREAPP // compiled against Mono's corlib, the indexer is "not supported by the language" (CS0570)
        [Test]
        public void TheScan_FindsAReadOnlySpanIndexerCall_WhereThereIsOne()
        {
            MethodInfo probe = typeof(MonoCorlibTests).GetMethod(nameof(IndexesAReadOnlySpan), BindingFlags.NonPublic | BindingFlags.Static)!;
            Assert.That(Callees(probe).Any(c => c.Name == "get_Item" && c.DeclaringType!.GetGenericTypeDefinition() == typeof(ReadOnlySpan<>)), Is.True);
        }

        private static double IndexesAReadOnlySpan(ReadOnlySpan<double> values) => values[0];
#endif

        /// <summary>Every method a method's IL calls (call, callvirt, newobj, ldftn, ldvirtftn), decoded opcode by opcode.</summary>
        private static IEnumerable<MethodBase> Callees(MethodBase method)
        {
            byte[]? il = method.GetMethodBody()?.GetILAsByteArray();
            if (il == null)
            {
                yield break;
            }

            Type[]? typeArgs = method.DeclaringType is { IsGenericType: true } t ? t.GetGenericArguments() : null;
            Type[]? methodArgs = method.IsGenericMethod ? method.GetGenericArguments() : null;
            int i = 0;
            while (i < il.Length)
            {
                short value = il[i] == 0xFE ? (short)(0xFE00 | il[i + 1]) : il[i];
                OpCode op = OpCodesByValue[value];
                i += op.Size;
                int operand = op.OperandType switch
                {
                    OperandType.InlineNone => 0,
                    OperandType.ShortInlineBrTarget or OperandType.ShortInlineI or OperandType.ShortInlineVar => 1,
                    OperandType.InlineVar => 2,
                    OperandType.InlineI8 or OperandType.InlineR => 8,
                    OperandType.InlineSwitch => 4 + 4 * BitConverter.ToInt32(il, i),
                    _ => 4,
                };
                if (op.OperandType == OperandType.InlineMethod)
                {
                    yield return method.Module.ResolveMethod(BitConverter.ToInt32(il, i), typeArgs, methodArgs)!;
                }

                i += operand;
            }
        }
    }
}
