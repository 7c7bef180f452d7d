using System;
using System.Runtime.InteropServices;

namespace MagnusBall
{
    /// <summary>
    /// Reads a <see cref="ReadOnlySpan{T}"/> through a <see cref="Span{T}"/> over the same memory (no copy).
    /// Debian's Mono 6.8 corlib declares <c>ReadOnlySpan&lt;T&gt;.this[int]</c> and its enumerator's
    /// <c>Current</c> without the <c>modreq(InAttribute)</c> that the C# compiler puts on a readonly-ref return,
    /// so netstandard2.1 code that indexes or <c>foreach</c>es a read-only span throws
    /// <c>MissingMethodException</c> there. <c>Span&lt;T&gt;</c>'s indexer returns a plain ref and works on every
    /// runtime; the library only reads through the view. <c>SpanViewTests</c> scans the library's IL for the two
    /// calls, so a new one fails on CoreCLR too, not only under Mono.
    /// </summary>
    internal static class SpanView
    {
        /// <summary>The same elements as a span (read them only).</summary>
        internal static Span<T> Of<T>(ReadOnlySpan<T> span) => MemoryMarshal.CreateSpan(ref MemoryMarshal.GetReference(span), span.Length);
    }
}
