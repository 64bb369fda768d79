-- book.lua: the pandoc filter of `t2 book build` (see chapters/README.md).
-- Metadata set by the builder: srcdir (folder of the page's source, relative to the repository
-- root; absent for generated pages), reporel (the repository root relative to the output folder)
-- and apimap (a file of "name<TAB>href" lines read from the Doxygen tag file).
--  * links to chapters/NN-slug/chapter.md (or to a later part of it, chapter-K.md) become
--    NN-slug.html, links to exercises/NNx-slug/README.md become exercises-NNx-slug.html;
--  * a paragraph "Continued in [...](chapter-2.md)." (a link to another part of the same
--    chapter) is for readers of the source files: the book, which makes one page of all the
--    parts, drops it;
--  * figures/... stay figures/... (the builder copies the figures next to the pages), and so do
--    animations/... (the builder writes the chapters' t2 animate pages there);
--  * any other relative link points to the file in the repository;
--  * inline code naming a library entity (`t2::orient`, `t2::orient(p, q, r)`) links to the API.

local srcdir, reporel, api = nil, "..", {}

local function meta_string(v)
  if v == nil then return nil end
  return pandoc.utils.stringify(v)
end

local function load_meta(meta)
  srcdir = meta_string(meta.srcdir)
  reporel = meta_string(meta.reporel) or ".."
  local f = meta_string(meta.apimap)
  if f then
    local h = io.open(f, "r")
    if h then
      for line in h:lines() do
        local name, href = line:match("^([^\t]+)\t(.+)$")
        if name then api[name] = href end
      end
      h:close()
    end
  end
end

-- dir/target with "." and ".." segments resolved; nil when it leaves the repository.
local function resolve(dir, target)
  local parts = {}
  for seg in (dir .. "/" .. target):gmatch("[^/]+") do
    if seg == ".." then
      if #parts == 0 then return nil end
      table.remove(parts)
    elseif seg ~= "." then
      table.insert(parts, seg)
    end
  end
  return table.concat(parts, "/")
end

local function rewrite(target)
  if srcdir == nil then return target end
  if target:match("^%a[%w+.-]*:") or target:sub(1, 1) == "#" or target:sub(1, 1) == "/" then
    return target
  end
  local path, frag = target:match("^([^#]*)(#?.*)$")
  if path == nil or path == "" then return target end
  local p = resolve(srcdir, path)
  if p == nil then return target end
  local ch = p:match("^chapters/(%d%d%-[^/]+)/chapter%.md$") or p:match("^chapters/(%d%d%-[^/]+)/chapter%-%d+%.md$")
  if ch then return ch .. ".html" .. frag end
  local ex = p:match("^exercises/(%d%d%l?%-[^/]+)/README%.md$")
  if ex then return "exercises-" .. ex .. ".html" .. frag end
  if p:match("^figures/") or p:match("^animations/") then return p .. frag end
  return reporel .. "/" .. p .. frag
end

local function api_href(text)
  local name = text:match("^([%w_:]+)")
  if name == nil then return nil end
  if text ~= name and not text:match("^[%w_:]+%s*[(<]") then return nil end
  if name:sub(1, 4) ~= "t2::" then name = "t2::" .. name end
  return api[name]
end

-- The page's first "# Title" becomes the document title (shown by the template above the body),
-- so that the table of contents lists the sections of the chapter.
local function lift_title(doc)
  local first = doc.blocks[1]
  if first and first.t == "Header" and first.level == 1 then
    doc.meta.title = pandoc.MetaInlines(first.content)
    doc.blocks:remove(1)
  end
  return doc
end

-- "Continued in [part 2](chapter-2.md)." (possibly emphasized): a paragraph that starts with
-- "Continued in" and links only to another part of the page's own chapter.
local function part_link_only(para)
  if srcdir == nil or not srcdir:match("^chapters/") then return false end
  if not pandoc.utils.stringify(para):match("^Continued in ") then return false end
  local targets = {}
  pandoc.walk_block(para, { Link = function(l) table.insert(targets, l.target) end })
  return #targets == 1 and (targets[1] == "chapter.md" or targets[1]:match("^chapter%-%d+%.md$") ~= nil)
end

return {
  { Meta = load_meta },
  { Para = function(p) if part_link_only(p) then return {} end end },
  { Pandoc = lift_title },
  { -- code that is already the text of a link stays as it is
    Link = function(l)
      for _, c in ipairs(l.content) do
        if c.t == "Code" then c.classes:insert("nolink") end
      end
      return l
    end },
  { Link = function(l) l.target = rewrite(l.target); return l end,
    Image = function(i) i.src = rewrite(i.src); return i end },
  { Code = function(c)
      if c.classes:includes("nolink") then return nil end
      local h = api_href(c.text)
      if h then return pandoc.Link({ c }, h, "", pandoc.Attr("", { "api" })) end
      return nil
    end },
}
